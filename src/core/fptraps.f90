!> Floating-point traps off and on around work that may raise them on purpose: reading a
!! value such as 1e400 (the run-time library overflows inside), or writing a rounded
!! 1.7e308 that reads back as an overflow.  The halting modes are saved and restored and the
!! flags raised in between cleared, so the checking build's traps (-ffpe-trap) stay armed
!! everywhere else.
module fptraps
    use, intrinsic :: ieee_arithmetic, only: ieee_usual, ieee_support_halting, &
        ieee_get_halting_mode, ieee_set_halting_mode, ieee_set_flag
    implicit none
    private

    public :: traps_off, traps_restore

    !> Size of the array traps_off fills (one mode per flag of ieee_usual).
    integer, parameter, public :: NTRAPS = size(ieee_usual)

contains

    !> Stop trapping overflow, division by zero and invalid (when traps are supported),
    !! remembering the halting modes in saved.
    subroutine traps_off(saved)
        logical, intent(out) :: saved(:)            !! halting modes of ieee_usual
        integer :: k
        do k = 1, size(ieee_usual)
            saved(k) = .false.
            if (ieee_support_halting(ieee_usual(k))) then
                call ieee_get_halting_mode(ieee_usual(k), saved(k))
                call ieee_set_halting_mode(ieee_usual(k), .false.)
            end if
        end do
    end subroutine traps_off

    !> Clear the flags raised since traps_off and restore the halting modes.
    subroutine traps_restore(saved)
        logical, intent(in) :: saved(:)             !! from traps_off
        integer :: k
        call ieee_set_flag(ieee_usual, .false.)
        do k = 1, size(ieee_usual)
            if (ieee_support_halting(ieee_usual(k))) &
                call ieee_set_halting_mode(ieee_usual(k), saved(k))
        end do
    end subroutine traps_restore

end module fptraps
