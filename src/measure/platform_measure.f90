!> Measurements on a platform with the body anywhere on it: the model of a period and of a
!! record is the platform's own (module platform_model for three cables, the elastic
!! cables' for four or more off the axis), not the bifilar equivalent with b = 2 radius
!! that pure torsion allows.
!!
!! A measurement's rig (rig_t) of cables > 2 is a regular platform (platform_of_rig: radius
!! b/2, radius_prime b_prime/2, every cable of length l, the mass centre at
!! x = r cos(lambda) - b_prime/2, y = cg_offset_y, depth r sin(lambda), the inertia of
!! module platform_geometry's platform_inertia).
!! * Centred (the mass centre on the axis): the periods are those of pure torsion, which
!!   the paper's bifilar with b = 2 radius, b' = 2 radius_prime gives exactly (the energy
!!   integral of module floquet) and which does not depend on the depth of the mass centre
!!   (eqs. (45)-(48) contain neither r nor lambda).  A record of three cables is the
!!   platform's own motion (below): the bifilar's runs carry its tilt about CD and its
!!   sway, modes the platform does not have (the bifilar tips with the mass centre above
!!   CD, and its pure torsion can be unstable where the platform's is not), which must not
!!   enter the fit.  Four or more cables (no inextensible model) keep the bifilar's pure
!!   torsion, the mass centre's depth taken positive (torsion_equivalent).
!! * Off the axis (offaxis_platform), three cables: a period is that of the platform's periodic
!!   torsion at the amplitude (module platform_orbit: the brake orbit from rest at
!!   yaw = rest + amplitude, found by shooting).
!!   Four or more cables: the elastic cables' periodic torsion (module
!!   platform_elastic_orbit, &cables stiffness; submodule platform_measure_elastic).
!! * Records of three cables, and of four or more off the axis (platform_records): the
!!   platform's motion released at rest turned by the amplitude about the vertical through
!!   its mass centre (module platform_model's platform_start; four or more cables the
!!   elastic cables' motion, platform_elastic's pe_start, Radau IIA), sampled as the yaw
!!   from rest (rad) or the rate about the downward vertical (rad/s), as the bifilar's
!!   theta4 and W = omega . n3 (n3 down) are.  The model turns about the mass centre with
!!   its sway: no parallel-axis correction is applied after.  I1 is the body's moment about
!!   the vertical through its mass centre, as everywhere.
!! * The rig must hold the body (platform_hold_check): the chart, a rest pose with every
!!   cable taut, and a stable one; a mass centre too high is refused naming the cg_depth at
!!   which the body tips (check_platform).
module platform_measure
    use kinds, only: dp, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_MODEL, ERR_NUMERIC
    use text, only: fixed, sci, itoa
    use rig, only: rig_t, start_t, accuracy_t
    use ode_system, only: integrator_t, integrator_stats_t
    use integrators, only: new_integrator
    use platform_geometry, only: platform_t, regular_platform, platform_inertia, QPSI
    use platform_model, only: check_platform, platform_start, platform_evaluate, &
        platform_motion_t, platform_sys_t
    use platform_orbit, only: platform_torsion_period
    implicit none
    private

    public :: offaxis_platform, platform_records, torsion_equivalent, measured_platform
    public :: platform_hold_check
    public :: platform_period_s, platform_record, platform_of_rig

    !> A mass centre within this fraction of radius_prime of the axis is on it.
    real(dp), parameter :: ON_AXIS = 1.0e-12_dp

    !> The most integrator steps of a record's run.
    integer, parameter :: RECORD_MAX_STEPS = 2000000


    interface
        !> The period (s) of the elastic platform rg (four or more cables, I1 in rg) at peak
        !! amplitude amp_deg (submodule platform_measure_elastic: the elastic orbit sits a
        !! floor above this module's other runs, and only this procedure needs it).
        module subroutine elastic_period_s(rg, acc, amp_deg, t, stat)
            type(rig_t), intent(in) :: rg
            type(accuracy_t), intent(in) :: acc
            real(dp), intent(in) :: amp_deg
            real(dp), intent(out) :: t
            type(status_t), intent(out) :: stat
        end subroutine elastic_period_s

        !> The record of the elastic platform rg (four or more cables, I1 and damping in rg)
        !! at the times taus (s after the release, increasing; those <= 0 see the start):
        !! released at rest turned by st%amplitude (degrees) about the vertical through the
        !! mass centre (platform_elastic's pe_start), the yaw from rest (rad) or omega . n3
        !! (rad/s) when rate; Radau IIA at acc's rtol and atol (submodule
        !! platform_measure_elastic).
        module subroutine elastic_record(rg, st, acc, taus, rate, vals, stat)
            type(rig_t), intent(in) :: rg
            type(start_t), intent(in) :: st
            type(accuracy_t), intent(in) :: acc
            real(dp), intent(in) :: taus(:)
            logical, intent(in) :: rate
            real(dp), intent(out) :: vals(:)
            type(status_t), intent(out) :: stat
        end subroutine elastic_record
    end interface
contains

    !> The regular platform of a rig_t of cables > 2 (radius b/2, radius_prime b_prime/2,
    !! every cable of length l; the mass centre from r and lambda: its offset along x
    !! r cos(lambda) - b_prime/2, along y cg_offset_y, its depth r sin(lambda)), in the
    !! rig's units, with its damping; not yet prepared (check_platform).
    pure function platform_of_rig(rg) result(pl)
        type(rig_t), intent(in) :: rg
        type(platform_t) :: pl
        pl = regular_platform(rg%cables, 0.5_dp*rg%b, 0.5_dp*rg%b_prime, rg%l, rg%mass, &
                              platform_inertia(rg%inertia, rg%btilde), &
                              [rg%r*cos(rg%lambda) - 0.5_dp*rg%b_prime, rg%cg_offset_y], &
                              rg%r*sin(rg%lambda), rg%g)
        pl%c_v = rg%c_v
        pl%c_q = rg%c_q
    end function platform_of_rig

    !> The mass centre's offset (x, y) from the axis of the platform rg (cables > 2).
    pure function platform_offset(rg) result(e)
        type(rig_t), intent(in) :: rg
        real(dp) :: e(2)
        e = [rg%r*cos(rg%lambda) - 0.5_dp*rg%b_prime, rg%cg_offset_y]
    end function platform_offset

    !> True for a platform (cables > 2) whose mass centre is off its axis: its periods and
    !! records are the platform model's, not pure torsion.
    pure logical function offaxis_platform(rg)
        type(rig_t), intent(in) :: rg
        offaxis_platform = .false.
        if (rg%cables <= 2) return
        offaxis_platform = maxval(abs(platform_offset(rg))) > ON_AXIS*0.5_dp*rg%b_prime
    end function offaxis_platform

    !> True for a platform whose records are the platform model's (platform_record): three
    !! cables, or a mass centre off the axis (four or more: the elastic cables' model).
    pure logical function platform_records(rg)
        type(rig_t), intent(in) :: rg
        platform_records = rg%cables == 3 .or. offaxis_platform(rg)
    end function platform_records

    !> The bifilar whose pure torsion is the centred platform's: the mass centre's depth
    !! taken positive (the torsion does not depend on it; see the module header).  Any other
    !! rig as it is.
    pure function torsion_equivalent(rg) result(re)
        type(rig_t), intent(in) :: rg
        type(rig_t) :: re
        re = rg
        if (rg%cables > 2 .and. .not. offaxis_platform(rg)) re%lambda = abs(rg%lambda)
    end function torsion_equivalent

    !> The platform of the measurement's rig with I1 = i1, checked and at rest
    !! (check_platform: ERR_DECK for a rig the cables cannot hold, ERR_MODEL naming the
    !! tipping height).  n = 3 only.
    subroutine measured_platform(rg, i1, pl, stat)
        type(rig_t), intent(in) :: rg
        real(dp), intent(in) :: i1
        type(platform_t), intent(out) :: pl
        type(status_t), intent(out) :: stat
        type(rig_t) :: rr
        rr = rg
        rr%inertia(1) = i1
        pl = platform_of_rig(rr)
        call check_platform(pl, stat)
    end subroutine measured_platform

    !> The platform of three cables holds the body at rest, stably (measured_platform); its
    !! message starts '&body' and says what to change.  Nothing for other rigs (two cables:
    !! module tip_check; four or more: no inextensible model).
    subroutine platform_hold_check(rg, stat)
        type(rig_t), intent(in) :: rg
        type(status_t), intent(inout) :: stat
        type(platform_t) :: pl
        type(status_t) :: st
        if (stat%code /= STATUS_OK .or. rg%cables /= 3) return
        call measured_platform(rg, rg%inertia(1), pl, st)
        if (st%code == STATUS_OK) return
        call set_error(stat, st%code, '&body: on the platform of 3 cables: '//st%msg)
    end subroutine platform_hold_check

    !> The period (s) of the periodic torsion of the off-axis platform rg with I1 = i1 at
    !! peak amplitude amp_deg: three cables platform_torsion_period, integrated with acc's
    !! rtol and integrator; four or more the elastic cables' (module platform_elastic_orbit,
    !! &cables stiffness, Radau IIA at acc's rtol and atol).
    subroutine platform_period_s(rg, acc, i1, amp_deg, t, stat)
        type(rig_t), intent(in) :: rg
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: i1, amp_deg
        real(dp), intent(out) :: t
        type(status_t), intent(out) :: stat
        type(platform_t) :: pl
        type(rig_t) :: rr
        t = 0.0_dp
        rr = rg
        rr%c_v = 0.0_dp
        rr%c_q = 0.0_dp
        if (rg%cables >= 4) then
            ! statically indeterminate when inextensible: the elastic cables' torsion
            rr%inertia(1) = i1
            call elastic_period_s(rr, acc, amp_deg, t, stat)
            return
        end if
        call measured_platform(rr, i1, pl, stat)
        if (stat%code /= STATUS_OK) return
        call platform_torsion_period(pl, amp_deg*deg, acc%rtol, acc%method, t, stat)
        if (stat%code /= STATUS_OK) stat%msg = 'the period at '//fixed(amp_deg, 3)// &
            ' deg (the platform''s periodic torsion): '//stat%msg
    end subroutine platform_period_s

    !> The platform's record at the sample times t(1:size(vals)) (s) with release at t0 (s):
    !! released at rest turned by st%amplitude (degrees) about the vertical through the mass
    !! centre; the yaw from rest (rad), or omega . n3 (rad/s) when rate.  A sample before t0
    !! sees the start.  Three cables: the inextensible platform integrated with acc (rtol,
    !! atol, integrator); four or more: the elastic cables' (elastic_record, &cables
    !! stiffness, Radau IIA at acc's rtol and atol).
    subroutine platform_record(rg, st, acc, t, t0, rate, vals, stat)
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: t(:), t0
        logical, intent(in) :: rate
        real(dp), intent(out) :: vals(:)
        type(status_t), intent(out) :: stat
        type(platform_t) :: pl
        real(dp), allocatable :: y0(:), taus(:)
        integer :: n, i0
        vals = 0.0_dp
        n = size(vals)
        if (rg%cables >= 4) then
            ! statically indeterminate when inextensible: the elastic cables' motion
            i0 = first_after(t(1:n), t0)
            vals(1:i0 - 1) = merge(0.0_dp, st%amplitude*deg, rate)
            call elastic_record(rg, st, acc, t(i0:n) - t0, rate, vals(i0:n), stat)
            if (stat%code /= STATUS_OK) stat%msg = 'the elastic platform''s record: '//stat%msg
            return
        end if
        call measured_platform(rg, rg%inertia(1), pl, stat)
        if (stat%code /= STATUS_OK) return
        allocate (y0(2*pl%nf))
        call platform_start(pl, st%amplitude*deg, y0, stat)
        if (stat%code /= STATUS_OK) return
        i0 = first_after(t(1:n), t0)
        vals(1:i0 - 1) = merge(0.0_dp, st%amplitude*deg, rate)
        if (i0 > n) return
        taus = t(i0:n) - t0
        if (.not. (taus(size(taus)) > 0.0_dp)) then
            ! (every sample at the release: the value at rest before it)
            vals = merge(0.0_dp, st%amplitude*deg, rate)
            return
        end if
        call integrate_samples(pl, y0, taus, acc, rate, vals(i0:n), stat)
        if (stat%code /= STATUS_OK) stat%msg = 'the platform''s record: '//stat%msg
    end subroutine platform_record

    !> The first of the increasing times t at or after t0 (size(t) + 1 when none).
    pure integer function first_after(t, t0) result(i0)
        real(dp), intent(in) :: t(:), t0
        integer :: i
        i0 = size(t) + 1
        do i = 1, size(t)
            if (t(i) >= t0) then
                i0 = i
                return
            end if
        end do
    end function first_after

    !> The run of pl from y0 (at rest, t = 0) sampled at the times taus (increasing, >= 0):
    !! the yaw from rest or the rate about the downward vertical, each sample checked finite
    !! with every cable taut (ERR_MODEL when one goes slack: the inextensible model ends).
    subroutine integrate_samples(pl, y0, taus, acc, rate, vals, stat)
        type(platform_t), intent(in) :: pl
        real(dp), intent(in) :: y0(:), taus(:)
        type(accuracy_t), intent(in) :: acc
        logical, intent(in) :: rate
        real(dp), intent(out) :: vals(:)
        type(status_t), intent(out) :: stat
        type(platform_sys_t) :: sys
        class(integrator_t), allocatable :: s
        type(integrator_stats_t) :: st
        real(dp) :: y(size(y0)), t_end, tn
        integer :: k, nt, nstep
        vals = 0.0_dp
        nt = size(taus)
        sys%pl = pl
        t_end = taus(nt)
        k = 1
        do while (k <= nt)
            if (taus(k) > 0.0_dp) exit
            call sample(y0, taus(k), vals(k))
            if (stat%code /= STATUS_OK) return
            k = k + 1
        end do
        if (k > nt) return
        call new_integrator(acc%method, s)
        call s%init(sys, 0.0_dp, y0, acc%rtol, [acc%atol], stat, tcrit=t_end)
        if (stat%code /= STATUS_OK) return
        nstep = 0
        do while (k <= nt)
            call s%step(sys, stat, tout=t_end)
            if (stat%code /= STATUS_OK) return
            nstep = nstep + 1
            st = s%stats()
            tn = st%t_current
            do while (k <= nt)
                if (taus(k) > tn) exit
                call s%dense(taus(k), 0, y, stat)
                if (stat%code == STATUS_OK) call sample(y, taus(k), vals(k))
                if (stat%code /= STATUS_OK) return
                k = k + 1
            end do
            if (nstep >= RECORD_MAX_STEPS .and. k <= nt) then
                call set_error(stat, ERR_NUMERIC, 'more than '//itoa(RECORD_MAX_STEPS)// &
                               ' integrator steps before t = '//sci(taus(k))//' s; raise '// &
                               '&integration rtol/atol')
                return
            end if
        end do
    contains
        !> One sample of state yy at time tt.
        subroutine sample(yy, tt, v)
            real(dp), intent(in) :: yy(:), tt
            real(dp), intent(out) :: v
            type(platform_motion_t) :: mo
            v = 0.0_dp
            call platform_evaluate(pl, yy, mo, stat)
            if (stat%code /= STATUS_OK) return
            if (rate) then
                ! the paper's W (its n3 points down): positive as the yaw from a positive
                ! release falls back, as theta4 and W of the bifilar's record
                v = -mo%omega(3)
            else
                v = mo%q(QPSI) - pl%q_ref(QPSI)
            end if
            if (.not. (abs(v) < huge(1.0_dp))) then
                call set_error(stat, ERR_NUMERIC, 'not finite at t = '//sci(tt)//' s')
            else if (any(mo%tension(1:pl%nd) <= 0.0_dp)) then
                call set_error(stat, ERR_MODEL, 'a cable goes slack at t = '//sci(tt)// &
                               ' s: the inextensible model ends; lower the amplitude')
            end if
        end subroutine sample
    end subroutine integrate_samples

end module platform_measure
