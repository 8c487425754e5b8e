!> The implementation of the work-precision analysis (submodule of work_precision): the
!! reference and its confirmation, the LSODA, Radau and RK4 points, the files.
submodule (work_precision) work_precision_impl
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC
    use geometry, only: pendulum_t
    use bifilar_model, only: bifilar_t, chart_energy, motion_t, NSTATE
    use ode_system, only: ode_system_t
    use elastic_model, only: elastic_t, elastic_start, elastic_atol, elastic_evaluate, &
                             elastic_chart, elastic_energy, ELASTIC_NSTATE, CABLE_AUTO, stretch_frequency
    use elastic_solver, only: elastic_solver_t
    use ode_system, only: integrator_t, integrator_stats_t
    use integrators, only: new_integrator, SOLVER_LSODA, SOLVER_RADAU
    use deck, only: deck_t, deck_echo
    use rig, only: make_pendulum, start_state
    use deck_runs, only: rig_of, start_of, output_times, scene_ready
    use kane_run, only: angle_difference, sway_of
    use output_io, only: out_files_t, all_finite
    use text, only: sci, itoa
    use unused_arg, only: unused
    use progress, only: progress_t
    implicit none

    real(dp), parameter :: MIN_CPU = 0.05_dp             !! repeat solves until this much CPU

    integer, parameter :: MAX_REPEATS = 100000

    !> model = 'elastic': most RK4 steps of one solve (finer RK4 points are left out), and
    !! the most substeps per output interval of the RK4 + Richardson reference check
    integer, parameter :: RK4_MAX_STEPS = 2000000

    integer, parameter :: REF_MAX_SUBSTEPS = 4096

contains

    !> LSODA from y0 at times(0) to every later time.
    module procedure solve_lsoda
        type(bifilar_t) :: sys
        sys%p = p
        call solve_lsoda_sys(sys, y0, times, rtol, [atol], ys, steps, nfe, stat)
    end procedure solve_lsoda

    !> LSODA on any system, atol of size 1 or n; the elastic model through elastic_solver
    !! (the cables' taut/slack switches located and restarted), by LSODA or, with method =
    !! SOLVER_RADAU, by Radau IIA.
    subroutine solve_lsoda_sys(sys, y0, times, rtol, atol, ys, steps, nfe, stat, method)
        class(ode_system_t), intent(inout) :: sys   !! the equations of motion
        real(dp), intent(in) :: y0(:)           !! state at times(0)
        real(dp), intent(in) :: times(0:)       !! output times, increasing
        real(dp), intent(in) :: rtol, atol(:)   !! tolerances
        real(dp), intent(out) :: ys(:, 0:)      !! (n, 0:nout) states at the times
        integer, intent(out) :: steps, nfe      !! integrator counters
        type(status_t), intent(out) :: stat     !! the integrator's failure
        integer, intent(in), optional :: method !! elastic model: SOLVER_LSODA (default) or
                                                !! SOLVER_RADAU
        class(integrator_t), allocatable :: solver
        type(elastic_solver_t) :: esolver
        integer :: m
        type(integrator_stats_t) :: st
        real(dp) :: tend
        integer :: k
        ys = 0.0_dp
        ys(:, 0) = y0
        tend = times(ubound(times, 1))
        select type (sys)
        type is (elastic_t)
            m = SOLVER_LSODA
            if (present(method)) m = method
            call esolver%init(sys, times(0), y0, rtol, atol, stat, tcrit=tend, method=m)
            do k = 1, ubound(times, 1)
                if (stat%code == 0) call esolver%integrate(sys, times(k), ys(:, k), stat)
            end do
            st = esolver%stats()
        class default
            call new_integrator(SOLVER_LSODA, solver)
            call solver%init(sys, times(0), y0, rtol, atol, stat, tcrit=tend)
            do k = 1, ubound(times, 1)
                if (stat%code == 0) call solver%integrate(sys, times(k), ys(:, k), stat)
            end do
            st = solver%stats()
        end select
        steps = st%steps
        nfe = st%rhs_evals
    end subroutine solve_lsoda_sys

    !> Fixed-step classical Runge-Kutta 4 with `m` equal steps per output interval.
    module procedure solve_rk4
        type(bifilar_t) :: sys
        sys%p = p
        call solve_rk4_sys(sys, y0, times, m, ys, steps, nfe, stat)
    end procedure solve_rk4

    !> Fixed-step RK4 on any system (the paper's or the elastic model).
    module procedure solve_rk4_sys
        real(dp), dimension(size(y0)) :: y, k1, k2, k3, k4
        real(dp) :: h, t
        integer :: k, j
        character(len=120) :: buf
        ys = 0.0_dp
        ys(:, 0) = y0
        y = y0
        steps = 0
        nfe = 0
        stat%code = 0
        do k = 1, ubound(times, 1)
            h = (times(k) - times(k - 1))/m
            do j = 1, m
                t = times(k - 1) + (j - 1)*h
                call sys%rhs(t, y, k1, stat)
                if (stat%code == 0) call sys%rhs(t + 0.5_dp*h, y + 0.5_dp*h*k1, k2, stat)
                if (stat%code == 0) call sys%rhs(t + 0.5_dp*h, y + 0.5_dp*h*k2, k3, stat)
                if (stat%code == 0) call sys%rhs(t + h, y + h*k3, k4, stat)
                nfe = nfe + 4
                if (stat%code /= 0) return
                y = y + (h/6.0_dp)*(k1 + 2.0_dp*k2 + 2.0_dp*k3 + k4)
                steps = steps + 1
                if (.not. all_finite(y)) then
                    write (buf, '(a,es10.3,a,es10.3)') 'RK4 with h = ', h, &
                        ' became unstable at tau = ', t + h
                    call set_error(stat, ERR_NUMERIC, trim(buf))
                    return
                end if
            end do
            ys(:, k) = y
        end do
    end procedure solve_rk4_sys

    !> Errors of a trajectory against the reference at the output times, and its energy
    !! error against its own start.
    module procedure trajectory_errors
        real(dp) :: e0
        integer :: k
        err_theta = 0.0_dp
        err_q = 0.0_dp
        err_energy = 0.0_dp
        e0 = chart_energy(p, ys(:, 0))
        do k = 0, ubound(ys, 2)
            err_theta = max(err_theta, angle_difference(ys(:, k), yref(:, k)))
            err_q = max(err_q, abs(sway_of(p, ys(:, k)) - sway_of(p, yref(:, k))))
            err_energy = max(err_energy, abs(chart_energy(p, ys(:, k)) - e0))
        end do
    end procedure trajectory_errors

    !> The analysis: reference, its confirmation, both curves, the two files.  With `files`
    !! the files join the run's others (see run_simulation); without it they are committed
    !! at the end.
    module procedure run_work_precision
        type(out_files_t), target :: own
        type(out_files_t), pointer :: fs
        type(progress_t) :: pr
        type(pendulum_t) :: p
        real(dp), allocatable :: times(:), yref(:, :), ys(:, :), yh1(:, :), yh2(:, :)
        real(dp) :: y0(NSTATE), th0(5), ratio, e1
        integer :: n, i, steps, nfe, m, ns, m_rk0
        character(len=:), allocatable :: path, path2
        integer :: u, ios
        logical :: loud, elastic, ref_check
        type(bifilar_t) :: kane
        type(elastic_t) :: el
        real(dp), allocatable :: y0s(:)

        fs => own
        if (present(files)) fs => files
        loud = .true.
        if (present(quiet)) loud = .not. quiet
        call make_pendulum(rig_of(d), p, stat)
        if (stat%code /= 0) return
        call start_state(start_of(d), p, y0, th0, stat)
        if (stat%code /= 0) return
        call output_times(d, times)
        n = ubound(times, 1)
        res%nout = n
        ! the system: the paper's, or the elastic model (same start, per-state atol, and RK4
        ! from its explicit stability bound h <= 1/omega_s up)
        elastic = trim(d%scene%model) == 'elastic'
        m_rk0 = 1
        if (elastic) then
            el%p = p
            el%stiffness = d%cables%stiffness
            el%damping = d%cables%damping
            ns = ELASTIC_NSTATE
            allocate (y0s(ns))
            call elastic_start(el, y0, y0s, stat)
            if (stat%code /= 0) then
                stat%msg = 'elastic start: '//stat%msg
                return
            end if
            do while (d%integration%dtau_out/m_rk0*stretch_frequency(el) > 1.0_dp .and. &
                      m_rk0 < 2**20)
                m_rk0 = 2*m_rk0
            end do
        else
            kane%p = p
            ns = NSTATE
            y0s = y0
        end if
        allocate (yref(ns, 0:n), ys(ns, 0:n), yh1(ns, 0:n), yh2(ns, 0:n))
        ratio = d%integration%atol/d%integration%rtol

        ! reference and its independent confirmation (elastic model: Radau, confirmed by LSODA)
        if (elastic) then
            call run_adaptive(WP_REF_RTOL, yref, stat, .true., SOLVER_RADAU)
            if (stat%code /= 0) then
                stat%msg = 'work_precision reference (Radau rtol 1e-13): '//stat%msg
                return
            end if
            call run_adaptive(WP_REF_RTOL, ys, stat, .true., SOLVER_LSODA)
            if (stat%code /= 0) then
                stat%msg = 'work_precision reference check (LSODA rtol 1e-13): '// &
                           stat%msg
                return
            end if
            call errors(ys, yref, res%ref_second_theta, res%ref_second_q, e1)
        else
            call run_adaptive(WP_REF_RTOL, yref, stat, .true., SOLVER_LSODA)
            if (stat%code /= 0) then
                stat%msg = 'work_precision reference (LSODA rtol 1e-13): '//stat%msg
                return
            end if
        end if
        m = max(WP_REF_SUBSTEPS, 4*m_rk0)
        res%ref_h = d%integration%dtau_out/m
        ! elastic model: the RK4 check is left out when it would take too many steps
        ref_check = 2*m <= REF_MAX_SUBSTEPS .and. real(2*m, dp)*n <= RK4_MAX_STEPS
        if (ref_check) then
            call run_rk4(m, yh1, stat)
            if (stat%code == 0) call run_rk4(2*m, yh2, stat)
            if (stat%code /= 0) then
                stat%msg = 'work_precision reference check (RK4): '//stat%msg
                return
            end if
            yh2 = (16.0_dp*yh2 - yh1)/15.0_dp
            call errors(yh2, yref, res%ref_agreement_theta, res%ref_agreement_q, e1)
        else
            res%ref_agreement_theta = -1.0_dp
            res%ref_agreement_q = -1.0_dp
        end if
        if (loud) write (*, '(a)') d%name//': work_precision reference '//ref_name()// &
            ' rtol 1e-13 against RK4 + Richardson (h = '//sci(res%ref_h, 2)// &
            '): angles agree to '//sci(res%ref_agreement_theta, 2)//', Q to '// &
            sci(res%ref_agreement_q, 2)
        if (loud .and. elastic) write (*, '(a)') d%name//': work_precision reference Radau '// &
            'rtol 1e-13 against LSODA rtol 1e-13: angles agree to '// &
            sci(res%ref_second_theta, 2)//', Q to '//sci(res%ref_second_q, 2)

        ! LSODA curve (and Radau's for the elastic model), then the fixed-step RK4 curve (one
        ! line of progress on a terminal)
        call pr%start(d%name//': work_precision', WP_NRTOL*merge(2, 1, elastic) + WP_NRK4)
        do i = 1, WP_NRTOL
            res%lsoda(i)%rtol = 10.0_dp**(-2 - i)
            call measure(res%lsoda(i), 0, SOLVER_LSODA)
            call pr%tick()
            if (.not. elastic) cycle
            res%radau(i)%rtol = res%lsoda(i)%rtol
            call measure(res%radau(i), 0, SOLVER_RADAU)
            call pr%tick()
        end do
        do i = 1, WP_NRK4
            m = m_rk0*2**(i - 1)
            res%rk4(i)%h = d%integration%dtau_out/m
            call pr%tick()
            if (real(m, dp)*n > RK4_MAX_STEPS) cycle
            call measure(res%rk4(i), m, SOLVER_LSODA)
        end do
        call pr%finish()

        ! files
        path = outdir//'/'//d%name//'.wp.dat'
        call fs%open(path, u, stat)
        if (stat%code /= 0) return
        ios = 0
        call header(u, 'LSODA, rtol = 1e-3 ... 1e-12, atol = rtol * (deck atol / deck rtol)')
        if (ios == 0) write (u, '(a)', iostat=ios) '# rtol cpu_seconds steps rhs_evaluations '// &
            'error_theta error_Q max_abs_energy_error'
        do i = 1, WP_NRTOL
            if (.not. res%lsoda(i)%ok) cycle
            if (ios == 0) write (u, '(es11.3e3,es15.6e3,2i10,3es15.6e3)', iostat=ios) &
                res%lsoda(i)%rtol, res%lsoda(i)%cpu_seconds, res%lsoda(i)%steps, &
                res%lsoda(i)%rhs_evaluations, res%lsoda(i)%error_theta, res%lsoda(i)%error_q, &
                res%lsoda(i)%max_abs_energy_error
        end do
        path2 = outdir//'/'//d%name//'.wp_rk4.dat'
        call fs%close(u, ios, stat)
        if (stat%code /= 0) return
        if (elastic) then
            path = outdir//'/'//d%name//'.wp_radau.dat'
            call fs%open(path, u, stat)
            if (stat%code /= 0) return
            call header(u, 'Radau IIA (generalized coordinates), rtol = 1e-3 ... 1e-12, atol = '// &
                'rtol * (deck atol / deck rtol)')
            if (ios == 0) write (u, '(a)', iostat=ios) '# rtol cpu_seconds steps '// &
                'rhs_evaluations error_theta error_Q max_abs_energy_error'
            do i = 1, WP_NRTOL
                if (.not. res%radau(i)%ok) cycle
                if (ios == 0) write (u, '(es11.3e3,es15.6e3,2i10,3es15.6e3)', iostat=ios) &
                    res%radau(i)%rtol, res%radau(i)%cpu_seconds, res%radau(i)%steps, &
                    res%radau(i)%rhs_evaluations, res%radau(i)%error_theta, &
                    res%radau(i)%error_q, res%radau(i)%max_abs_energy_error
            end do
            call fs%close(u, ios, stat)
            if (stat%code /= 0) return
        end if
        call fs%open(path2, u, stat)
        if (stat%code /= 0) return
        call header(u, 'fixed-step classical Runge-Kutta 4, h = dtau_out / 2**k (elastic '// &
            'model: from h <= 1/omega_s down, at most 2e6 steps per solve)')
        if (ios == 0) write (u, '(a)', iostat=ios) '# h cpu_seconds steps rhs_evaluations '// &
            'error_theta error_Q max_abs_energy_error'
        do i = 1, WP_NRK4
            if (.not. res%rk4(i)%ok) cycle
            if (ios == 0) write (u, '(es11.3e3,es15.6e3,2i10,3es15.6e3)', iostat=ios) &
                res%rk4(i)%h, res%rk4(i)%cpu_seconds, res%rk4(i)%steps, &
                res%rk4(i)%rhs_evaluations, res%rk4(i)%error_theta, res%rk4(i)%error_q, &
                res%rk4(i)%max_abs_energy_error
        end do
        call fs%close(u, ios, stat)
        if (present(files)) return
        if (stat%code == 0) call own%commit(stat)
        if (stat%code /= 0) call own%discard()

    contains

        !> One point of a curve: LSODA or Radau (method) at pt%rtol (mm = 0) or RK4 with mm
        !! steps per output interval, solved repeatedly until MIN_CPU; its CPU per solve,
        !! counters and errors against the reference into pt (pt%ok: finished, all finite).
        subroutine measure(pt, mm, method)
            type(wp_point_t), intent(inout) :: pt
            integer, intent(in) :: mm, method
            real(dp) :: total, c0, c1, e1, e2, e3
            integer :: nrep
            type(status_t) :: s1
            total = 0.0_dp
            nrep = 0
            do while (total < MIN_CPU .and. nrep < MAX_REPEATS)
                call cpu_time(c0)
                if (mm > 0) then
                    call run_rk4(mm, ys, s1)
                else
                    call run_adaptive(pt%rtol, ys, s1, .false., method)
                end if
                call cpu_time(c1)
                total = total + (c1 - c0)
                nrep = nrep + 1
                if (s1%code /= 0) exit
            end do
            pt%ok = s1%code == 0
            if (.not. pt%ok) return
            pt%cpu_seconds = total/nrep
            pt%steps = steps
            pt%rhs_evaluations = nfe
            call errors(ys, yref, e1, e2, e3)
            pt%error_theta = e1
            pt%error_q = e2
            pt%max_abs_energy_error = e3
            pt%ok = all_finite([e1, e2, e3, pt%cpu_seconds])
        end subroutine measure

        !> LSODA or Radau (method; the elastic model only) on the deck's system at rtol,
        !! atol = rtol * ratio (LSODA on the elastic model: per state from elastic_atol, the
        !! velocities' tolerance with the rtol term as in a simulation, without it, tighter,
        !! for the reference; Radau uses atol(1)); steps and nfe of the host are set.
        subroutine run_adaptive(rtl, yout, st, reference, method)
            real(dp), intent(in) :: rtl
            real(dp), intent(out) :: yout(:, 0:)
            type(status_t), intent(out) :: st
            logical, intent(in) :: reference
            integer, intent(in) :: method
            if (elastic .and. reference) then
                call solve_lsoda_sys(el, y0s, times, rtl, elastic_atol(el, rtl*ratio), &
                                     yout, steps, nfe, st, method)
            else if (elastic) then
                call solve_lsoda_sys(el, y0s, times, rtl, elastic_atol(el, rtl*ratio, rtl), &
                                     yout, steps, nfe, st, method)
            else
                call solve_lsoda_sys(kane, y0s, times, rtl, [rtl*ratio], yout, steps, nfe, st)
            end if
        end subroutine run_adaptive

        !> RK4 on the deck's system, mm steps per output interval.
        subroutine run_rk4(mm, yout, st)
            integer, intent(in) :: mm
            real(dp), intent(out) :: yout(:, 0:)
            type(status_t), intent(out) :: st
            if (elastic) then
                el%mode = CABLE_AUTO             ! the law decided at each evaluation
                call solve_rk4_sys(el, y0s, times, mm, yout, steps, nfe, st)
            else
                call solve_rk4_sys(kane, y0s, times, mm, yout, steps, nfe, st)
            end if
        end subroutine run_rk4

        !> Errors of a trajectory of the deck's system against the reference.
        subroutine errors(yt, yr, err_theta, err_q, err_energy)
            real(dp), intent(in) :: yt(:, 0:), yr(:, 0:)
            real(dp), intent(out) :: err_theta, err_q, err_energy
            if (elastic) then
                el%mode = CABLE_AUTO             ! energies by the law, whatever the last run left
                call elastic_errors(el, yt, yr, err_theta, err_q, err_energy)
            else
                call trajectory_errors(p, yt, yr, err_theta, err_q, err_energy)
            end if
        end subroutine errors

        !> The '#' lines of a file; the writes' iostat in ios (host).
        subroutine header(unit, what)
            integer, intent(in) :: unit
            character(len=*), intent(in) :: what
            if (ios == 0) write (unit, '(a)', iostat=ios) '# bifilar work-precision: '// &
                trim(d%scene%title)
            if (ios == 0) write (unit, '(a)', iostat=ios) '# '//what//'; errors at the '// &
                'output times against the reference (angles in rad, Q over b'', energy over '// &
                'm g b'')'
            if (ios == 0) write (unit, '(a)', iostat=ios) '# reference: '//ref_name()// &
                ' rtol 1e-13; confirmed by RK4 + Richardson (h = '//sci(res%ref_h, 2)// &
                ' and h/2): angles agree to '//sci(res%ref_agreement_theta, 2)//', Q to '// &
                sci(res%ref_agreement_q, 2)
            if (elastic .and. ios == 0) write (unit, '(a)', iostat=ios) '# reference '// &
                'confirmed by LSODA rtol 1e-13 (maximal coordinates): angles agree to '// &
                sci(res%ref_second_theta, 2)//', Q to '//sci(res%ref_second_q, 2)
            call deck_echo(d, unit, ios)
        end subroutine header

        !> The integrator of the reference.
        function ref_name() result(nm)
            character(len=:), allocatable :: nm
            nm = 'LSODA'
            if (elastic) nm = 'Radau'
        end function ref_name

    end procedure run_work_precision

    !> The preconditions (deck_runs's scene_ready).
    module procedure work_precision_ready
        call unused(self)
        call scene_ready(d, stat)
    end procedure work_precision_ready

    !> The run (run_work_precision, quiet, into the run's files).
    module procedure work_precision_run
        call unused(options)
        call run_work_precision(d, outdir, self%res, stat, quiet=.true., files=files)
    end procedure work_precision_run

    !> ' work_precision N LSODA, [N Radau,] N RK4 points, reference confirmed to E rad;'
    module procedure work_precision_summary
        s = ' work_precision '//itoa(count(self%res%lsoda%ok))//' LSODA, '
        if (trim(d%scene%model) == 'elastic') s = s//itoa(count(self%res%radau%ok))//' Radau, '
        s = s//itoa(count(self%res%rk4%ok))//' RK4 points, reference confirmed to '// &
            sci(self%res%ref_agreement_theta, 1)//' rad;'
    end procedure work_precision_summary

    !> trajectory_errors for the elastic model: angles from the body's pose (elastic_chart,
    !! theta1 and theta4 continued to the reference's branch), Q and the energy (springs'
    !! included) from elastic_evaluate.
    subroutine elastic_errors(el, ys, yref, err_theta, err_q, err_energy)
        type(elastic_t), intent(in) :: el       !! the elastic system
        real(dp), intent(in) :: ys(:, 0:)       !! trajectory at the output times
        real(dp), intent(in) :: yref(:, 0:)     !! reference at the same times
        real(dp), intent(out) :: err_theta, err_q, err_energy
        real(dp) :: c1(NSTATE), c2(NSTATE), thr(5), e0
        type(motion_t) :: m1, m2
        type(status_t) :: st
        integer :: k
        err_theta = 0.0_dp
        err_q = 0.0_dp
        err_energy = 0.0_dp
        e0 = elastic_energy(el, ys(:, 0))
        thr = 0.0_dp
        do k = 0, ubound(ys, 2)
            c2 = elastic_chart(el%p, yref(:, k), thr)
            thr = [c2(1), 0.0_dp, 0.0_dp, c2(4), c2(5)]
            c1 = elastic_chart(el%p, ys(:, k), thr)
            err_theta = max(err_theta, angle_difference(c1, c2))
            call elastic_evaluate(el, ys(:, k), 0.0_dp, m1, st)
            if (st%code == 0) call elastic_evaluate(el, yref(:, k), 0.0_dp, m2, st)
            if (st%code /= 0) then
                err_q = huge(1.0_dp)
                cycle
            end if
            err_q = max(err_q, abs(m1%q_sway - m2%q_sway))
            err_energy = max(err_energy, abs(m1%energy - e0))
        end do
    end subroutine elastic_errors

end submodule work_precision_impl
