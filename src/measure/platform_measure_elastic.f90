!> The period and the record of a platform of four or more cables from its elastic cables
!! (modules platform_elastic and platform_elastic_orbit: &cables stiffness, Radau IIA at the
!! accuracy's rtol and atol).  A submodule of platform_measure, so that the modules using
!! platform_measure stay below the elastic orbit's floor.
!!
!! The record: the elastic platform at its elastic rest pose (elastic_platform_ready, the
!! rig's damping about the vertical put back), released at rest turned by the amplitude
!! about the vertical through the mass centre with the cables' stretches on the slow motion
!! (pe_start, as the periodic torsion starts but with no sway: the same release as the
!! three cables' record), each cable kept taut (a slack one ends the record with ERR_MODEL,
!! as the inextensible model's does); the rates' absolute tolerances scaled as
!! platform_elastic's pe_atol says (with atol on every rate, 40 times the steps).
submodule (platform_measure) platform_measure_elastic
    use integrators, only: SOLVER_RADAU
    use platform_geometry, only: PLATFORM_NMAX
    use platform_elastic, only: platform_elastic_t, pe_start, pe_switch, pe_evaluate, &
                                pe_motion_t, pe_atol, PE_NSTATE
    use platform_elastic_orbit, only: elastic_torsion_period, elastic_platform_ready
    implicit none
contains

    module subroutine elastic_period_s(rg, acc, amp_deg, t, stat)
        type(rig_t), intent(in) :: rg
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: amp_deg
        real(dp), intent(out) :: t
        type(status_t), intent(out) :: stat
        call elastic_torsion_period(platform_of_rig(rg), rg%cable_stiffness, amp_deg*deg, &
                                    acc%rtol, acc%atol, t, stat)
        if (stat%code /= STATUS_OK) stat%msg = 'the period at '//fixed(amp_deg, 3)// &
            ' deg (the elastic platform''s periodic torsion): '//stat%msg
    end subroutine elastic_period_s

    module subroutine elastic_record(rg, st, acc, taus, rate, vals, stat)
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: taus(:)
        logical, intent(in) :: rate
        real(dp), intent(out) :: vals(:)
        type(status_t), intent(out) :: stat
        type(platform_t) :: pl
        type(platform_elastic_t) :: el
        class(integrator_t), allocatable :: s
        type(integrator_stats_t) :: ss
        real(dp) :: q_rest(6), y0(PE_NSTATE), y(PE_NSTATE), t_end, tn
        integer :: k, nt, nstep
        vals = 0.0_dp
        pl = platform_of_rig(rg)
        call elastic_platform_ready(pl, rg%cable_stiffness, el, q_rest, stat)
        if (stat%code /= STATUS_OK) return
        ! the rest pose does not depend on the damping; the motion does
        el%pl%c_v = pl%c_v
        el%pl%c_q = pl%c_q
        call pe_start(el, q_rest, st%amplitude*deg, y0, stat)
        if (stat%code /= STATUS_OK) return
        nt = size(taus)
        k = 1
        do while (k <= nt)
            if (taus(k) > 0.0_dp) exit
            call sample(y0, taus(k), vals(k))
            if (stat%code /= STATUS_OK) return
            k = k + 1
        end do
        if (k > nt) return
        t_end = taus(nt)
        call new_integrator(SOLVER_RADAU, s)
        call s%init(el, 0.0_dp, y0, acc%rtol, pe_atol(el, acc%atol), stat, tcrit=t_end)
        if (stat%code /= STATUS_OK) return
        nstep = 0
        do while (k <= nt)
            call s%step(el, stat, tout=t_end)
            if (stat%code /= STATUS_OK) return
            nstep = nstep + 1
            ss = s%stats()
            tn = ss%t_current
            ! every cable taut at the step's end (the smooth law of CABLE_TAUT would pull on
            ! a slack cable)
            call s%dense(tn, 0, y, stat)
            if (stat%code == STATUS_OK) call taut(y, tn)
            if (stat%code /= STATUS_OK) return
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
        !> ERR_MODEL when a cable is slack at state yy, time tt.
        subroutine taut(yy, tt)
            real(dp), intent(in) :: yy(:), tt
            real(dp) :: g(PLATFORM_NMAX)
            call pe_switch(el, yy, g(1:el%pl%n), stat)
            if (stat%code /= STATUS_OK) return
            if (any(.not. (g(1:el%pl%n) > 0.0_dp))) &
                call set_error(stat, ERR_MODEL, 'a cable goes slack at t = '//sci(tt)// &
                               ' s (the torsion of taut cables ends); lower the amplitude '// &
                               'or move the mass centre towards the axis')
        end subroutine taut

        !> One sample of state yy at time tt.
        subroutine sample(yy, tt, v)
            real(dp), intent(in) :: yy(:), tt
            real(dp), intent(out) :: v
            type(pe_motion_t) :: mo
            v = 0.0_dp
            call pe_evaluate(el, yy, mo, stat)
            if (stat%code /= STATUS_OK) return
            if (rate) then
                ! the paper's W (its n3 points down), as the three cables' record
                v = -mo%omega(3)
            else
                v = mo%q(QPSI) - el%pl%q_ref(QPSI)
            end if
            if (.not. (abs(v) < huge(1.0_dp))) &
                call set_error(stat, ERR_NUMERIC, 'not finite at t = '//sci(tt)//' s')
        end subroutine sample
    end subroutine elastic_record

end submodule platform_measure_elastic
