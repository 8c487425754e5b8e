!> A body above the cables of a bifilar tips over.
!!
!! Hung from two cables, a body turns freely about the line CD of its attachment points:
!! that rotation changes no cable's length, so only gravity acts on it.  With the mass
!! centre below CD (depth r sin(lambda) > 0) gravity brings it back; above CD it tips the
!! body over, and no measurement of it swings as the model says.  A platform of three or
!! more cables holds the tilt with its cables, so there a body may sit above its
!! attachments (&body cg_depth < 0), up to the height at which the platform tips: a
!! platform of three cables is checked by its own model (module platform_measure's
!! platform_hold_check: a rest pose with every cable taut, stable, else refused naming the
!! cg_depth at which it tips).
module tip_check
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_MODEL
    use text, only: sci
    use rig, only: rig_t
    use platform_measure, only: platform_hold_check
    implicit none
    private

    public :: check_not_tipping

contains

    !> ERR_MODEL (exit 4) for a rig of two cables whose mass centre is above the line CD, or
    !! a platform of three cables that tips (ERR_DECK when its cables cannot hold the body).
    subroutine check_not_tipping(rg, cables, stat)
        type(rig_t), intent(in) :: rg
        integer, intent(in) :: cables           !! &suspension cables
        type(status_t), intent(inout) :: stat
        real(dp) :: depth
        if (stat%code /= 0) return
        if (cables > 2) then
            call platform_hold_check(rg, stat)
            return
        end if
        depth = rg%r*sin(rg%lambda)
        if (.not. (depth < 0.0_dp)) return
        call set_error(stat, ERR_MODEL, '&body: the mass centre is '//sci(-depth, 4)// &
            ' above the line CD of the two cables (cg_depth = '//sci(depth, 4)//', or r sin'// &
            '(lambda) < 0): the body tips over about CD, which no cable resists; only a '// &
            'platform of three or more cables (&suspension cables >= 3) holds a body above '// &
            'its attachments; allowed with two cables: cg_depth >= 0 (r sin(lambda) >= 0)')
    end subroutine check_not_tipping

end module tip_check
