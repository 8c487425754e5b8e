!> Benchmark of the elastic-cable model (make bench), three tables.
!!
!! 1. The grid: the Figs. 4-6 cylinder (l = 2 b', l' = 1.8 b', raised 45 deg),
!!    tau = 0 ... 20, output every 0.05, atol = rtol/100, stiffness k = 1e3 ... 1e8, damping
!!    ratio 0.01, 0.1, 0.5.  For each (k, zeta) the reference (Radau IIA, rtol 1e-13, in the
!!    generalized coordinates) and its agreement with two methods in the maximal coordinates:
!!    LSODA at rtol 1e-13, and fixed-step RK4 at h and h/2 combined by Richardson
!!    extrapolation (h = 0.05/2^j, the largest with h omega_s <= 0.5, the law decided at each
!!    evaluation, no cable modes); then Radau at rtol 1e-6 ... 1e-10:
!!    the largest error in theta1, theta4, theta5 and Q over rtol, and its steps; and its
!!    steps at rtol 1e-12.  File: OUT_grid.dat.
!! 2. Equal accuracy at k = 1e6 and 1e8, damping 0.01: Radau at rtol 1e-7 ... 1e-11 and
!!    LSODA at rtol 1e-8, 1e-10, 1e-12: theta1 error, steps, right-hand sides, Jacobians,
!!    CPU, beside SUNDIALS CVODE's figures.  File: OUT_accuracy.dat.
!! 3. Stiffness, damping 0.5, tau = 0 ... 4 pi, rtol 1e-8: LSODA with the cables' modes
!!    (steps, evaluations, failures, last method; CPU best of 3), Radau beside it (and Radau
!!    kept in the maximal coordinates: steps, Newton failures), fixed-step
!!    RK4 at the fewest steps with which it stays stable (|energy error| < 1e-3 at the end,
!!    by bisection) and its predicted bound 2.8/omega_s, and LSODA kept in Adams
!!    (nonstiff_only).  File: OUT (default output/bench_elastic.dat).
program bench_elastic
    use kinds, only: dp, pi
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, start_of
    use rig, only: make_pendulum, start_state
    use bifilar_model, only: NSTATE
    use elastic_model, only: elastic_t, elastic_start, elastic_atol, elastic_energy, &
                             stretch_frequency, ELASTIC_NSTATE, CABLE_AUTO
    use elastic_solver, only: elastic_solver_t, SOLVER_LSODA, SOLVER_RADAU
    use ode_system, only: METHOD_BDF
    use work_precision, only: solve_rk4_sys
    use output_io, only: atomic_open, atomic_commit
    use test_elastic_radau, only: issue_scene, scene_errors, solve_scene, NOUT, TEND
    use ode_system, only: integrator_stats_t
    implicit none
    character(len=1024) :: outpath
    character(len=:), allocatable :: base
    outpath = 'output/bench_elastic.dat'
    if (command_argument_count() >= 1) call get_command_argument(1, outpath)
    base = trim(outpath)
    if (len(base) > 4) then
        if (base(len(base) - 3:) == '.dat') base = base(1:len(base) - 4)
    end if
    call grid_table(base//'_grid.dat')
    call accuracy_table(base//'_accuracy.dat')
    call stiffness_table(trim(outpath))

contains

    !> Table 1 (see the header).
    subroutine grid_table(path)
        character(len=*), intent(in) :: path
        real(dp), parameter :: zz(3) = [0.01_dp, 0.1_dp, 0.5_dp]
        type(elastic_t) :: el
        type(integrator_stats_t) :: st, sl
        type(status_t) :: stat
        real(dp) :: y0(ELASTIC_NSTATE), err(2), agree(2), agree_rk(2), ratio(5), worst
        real(dp), allocatable :: yref(:, :), ys(:, :), yh(:, :), times(:)
        integer :: ik, iz, ir, u, steps(6), m, nst, nfe
        allocate (yref(ELASTIC_NSTATE, 0:NOUT), ys(ELASTIC_NSTATE, 0:NOUT))
        allocate (yh(ELASTIC_NSTATE, 0:NOUT), times(0:NOUT))
        times = [(ir*TEND/NOUT, ir = 0, NOUT)]
        call atomic_open(path, u, stat)
        if (stat%code /= 0) error stop 'bench_elastic: cannot write the grid file'
        write (u, '(a)') '# grid: cylinder l'' = 1.8, 45 deg, tau 0..20, '// &
            'atol = rtol/100;'// &
            ' Radau IIA (generalized coordinates); errors: max over theta1, theta4, theta5, Q'
        write (u, '(a)') '# stiffness damping ref_lsoda_agreement ref_rk4_richardson_agreement '// &
            'err_over_rtol(1e-6 ... 1e-10) steps(1e-6 ... 1e-10) steps_1e-12'
        write (*, '(/,a)') '1. Grid: cylinder l'' = 1.8, 45 deg, tau 0..20, '// &
            'atol = rtol/100; Radau IIA'
        write (*, '(a)') '   largest error in theta1, theta4, theta5, Q over rtol / steps, '// &
            'at rtol 1e-6 ... 1e-10; steps at 1e-12;'
        write (*, '(a)') '   reference Radau 1e-13; its agreement with LSODA 1e-13 and '// &
            'with RK4 + '// &
            'Richardson (maximal coordinates)'
        write (*, '(a8,a6,a10,a10,5a14,a9)') 'k', 'zeta', 'LSODA', 'RK4+R', '1e-6', '1e-7', &
            '1e-8', '1e-9', '1e-10', '1e-12'
        worst = 0.0_dp
        do ik = 3, 8
            do iz = 1, 3
                call issue_scene(10.0_dp**ik, zz(iz), el, y0)
                call solve_scene(el, y0, SOLVER_RADAU, 1.0e-13_dp, yref, st, stat)
                if (stat%code /= 0) error stop 'bench_elastic: reference failed'
                call solve_scene(el, y0, SOLVER_LSODA, 1.0e-13_dp, ys, sl, stat)
                agree = -1.0_dp
                if (stat%code == 0) agree = scene_errors(el, ys, yref)
                m = 1
                do while (TEND/NOUT/m*stretch_frequency(el) > 0.5_dp)
                    m = 2*m
                end do
                el%mode = CABLE_AUTO
                call solve_rk4_sys(el, y0, times, m, ys, nst, nfe, stat)
                if (stat%code == 0) call solve_rk4_sys(el, y0, times, 2*m, yh, nst, nfe, stat)
                agree_rk = -1.0_dp
                if (stat%code == 0) agree_rk = scene_errors(el, (16*yh - ys)/15, yref)
                do ir = 1, 5
                    call solve_scene(el, y0, SOLVER_RADAU, 10.0_dp**(-5 - ir), ys, st, stat)
                    err = scene_errors(el, ys, yref)
                    ratio(ir) = err(1)/10.0_dp**(-5 - ir)
                    if (stat%code /= 0) ratio(ir) = -1.0_dp
                    steps(ir) = st%steps
                end do
                call solve_scene(el, y0, SOLVER_RADAU, 1.0e-12_dp, ys, st, stat)
                steps(6) = st%steps
                worst = max(worst, maxval(ratio))
                write (*, '(es8.0,f6.2,2es10.2,5(f7.2,i7),i9)') 10.0_dp**ik, zz(iz), agree(1), &
                    agree_rk(1), (ratio(ir), steps(ir), ir = 1, 5), steps(6)
                write (u, '(es8.1,f6.2,2es11.3,5es11.3,6i8)') 10.0_dp**ik, zz(iz), agree(1), &
                    agree_rk(1), ratio, steps
            end do
        end do
        write (*, '(a,f6.2,a)') '   largest error over the grid: ', worst, ' rtol (goal: <= 30)'
        call atomic_commit(u, path, stat)
    end subroutine grid_table

    !> Table 2 (see the header).
    subroutine accuracy_table(path)
        character(len=*), intent(in) :: path
        real(dp), parameter :: rr(5) = [1.0e-7_dp, 1.0e-8_dp, 1.0e-9_dp, 1.0e-10_dp, 1.0e-11_dp]
        real(dp), parameter :: rl(3) = [1.0e-8_dp, 1.0e-10_dp, 1.0e-12_dp]
        type(elastic_t) :: el
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: y0(ELASTIC_NSTATE), err(2), cpu, c, stiff
        real(dp), allocatable :: yref(:, :), ys(:, :)
        integer :: ik, ir, u, rep
        allocate (yref(ELASTIC_NSTATE, 0:NOUT), ys(ELASTIC_NSTATE, 0:NOUT))
        call atomic_open(path, u, stat)
        if (stat%code /= 0) error stop 'bench_elastic: cannot write the accuracy file'
        write (u, '(a)') '# equal accuracy, damping 0.01, tau 0..20: method (1 LSODA, 2 Radau) '// &
            'stiffness rtol theta1_error steps rhs_evaluations jacobian_evaluations cpu_seconds'
        write (*, '(/,a)') '2. Equal accuracy, damping 0.01, tau 0..20 (CPU: Radau best of 3, '// &
            'LSODA one run)'
        write (*, '(a)') '   SUNDIALS CVODE 6.4.1: k = 1e6: 1 247 steps for 5.1e-4, '// &
            '36 717 for 2.1e-6, 37 791 for 2.5e-9;'
        write (*, '(a)') '   k = 1e8: 329 615 steps for 7.7e-6, 318 366 for 1.3e-7'
        write (*, '(a8,a7,a8,a12,a9,a10,a7,a10)') 'k', 'method', 'rtol', 'theta1 err', 'steps', &
            'rhs', 'jac', 'cpu s'
        do ik = 1, 2
            stiff = 10.0_dp**(4 + 2*ik)
            call issue_scene(stiff, 0.01_dp, el, y0)
            call solve_scene(el, y0, SOLVER_RADAU, 1.0e-13_dp, yref, st, stat)
            do ir = 1, size(rr)
                cpu = huge(1.0_dp)
                do rep = 1, 3
                    call solve_scene(el, y0, SOLVER_RADAU, rr(ir), ys, st, stat, c)
                    cpu = min(cpu, c)
                end do
                err = scene_errors(el, ys, yref)
                call row(u, stiff, 2, rr(ir), err(2), st, cpu)
            end do
            do ir = 1, size(rl)
                call solve_scene(el, y0, SOLVER_LSODA, rl(ir), ys, st, stat, cpu)
                err = scene_errors(el, ys, yref)
                call row(u, stiff, 1, rl(ir), err(2), st, cpu)
            end do
        end do
        call atomic_commit(u, path, stat)
    end subroutine accuracy_table

    !> One row of table 2, on the screen and in the file (unit u).
    subroutine row(u, stiff, method, rtol, err, st, cpu)
        integer, intent(in) :: u, method
        real(dp), intent(in) :: stiff, rtol, err, cpu
        type(integrator_stats_t), intent(in) :: st
        write (*, '(es8.0,a7,es8.0,es12.2,i9,i10,i7,f10.4)') stiff, &
            trim(merge('Radau', 'LSODA', method == 2)), rtol, err, st%steps, &
            st%rhs_evals, st%jac_evals, cpu
        write (u, '(i2,es9.1,es9.1,es11.3,3i9,es12.4)') method, stiff, rtol, err, &
            st%steps, st%rhs_evals, st%jac_evals, cpu
    end subroutine row

    !> Table 3 (see the header).
    subroutine stiffness_table(path)
        character(len=*), intent(in) :: path
        real(dp), parameter :: kk(3) = [1.0e4_dp, 1.0e6_dp, 1.0e8_dp], zeta = 0.5_dp
        real(dp), parameter :: tend = 4*pi, rtol = 1.0e-8_dp, atol = 1.0e-10_dp
        type(deck_t) :: d
        type(status_t) :: st
        type(elastic_t) :: el
        type(elastic_solver_t) :: s
        type(integrator_stats_t) :: ls, la, lr, lm
        real(dp) :: yc(NSTATE), th0(5), y0(ELASTIC_NSTATE), y(ELASTIC_NSTATE), a(ELASTIC_NSTATE)
        real(dp) :: best, bestr, t0, t1, ws, rk_cpu, adams_cpu
        integer :: j, rep, u, nrk
        call read_deck('input/cylinder_l180.nml', d, st)
        if (st%code /= 0) error stop 'bench_elastic: input/cylinder_l180.nml does not read'
        call make_pendulum(rig_of(d), el%p, st)
        call start_state(start_of(d), el%p, yc, th0, st)
        if (st%code /= 0) error stop 'bench_elastic: no start'
        call atomic_open(path, u, st)
        if (st%code /= 0) error stop 'bench_elastic: cannot write the result file'
        write (u, '(a)') '# bifilar benchmark: elastic cables, cylinder l = 2b, l'' = 1.8b, '// &
            '45 deg, damping 0.5, tau = 0 ... 4 pi, rtol 1e-8'
        write (u, '(a)') '# stiffness cpu_seconds steps rhs_evaluations jacobian_evaluations '// &
            'method_switches conv_failures error_test_failures last_method_bdf '// &
            'rk4_fewest_stable_steps rk4_bound_steps rk4_cpu_seconds adams_only_steps '// &
            'adams_only_rhs_evaluations adams_only_cpu_seconds radau_cpu_seconds radau_steps '// &
            'radau_rhs_evaluations radau_jacobian_evaluations radau_maximal_steps '// &
            'radau_maximal_newton_failures'
        write (*, '(/,a)') '3. Stiffness: cylinder l = 2b, l'' = 1.8b, 45 deg, damping 0.5, '// &
            'tau = 0 ... 4 pi (2 torsion periods), rtol 1e-8 (best of 3)'
        write (*, '(a10,a9,a8,a9,a7,a6,a6,a6,a7,a12,a11,a11,a12,a12,a10,a7,a8,a10,a8)') &
            'stiffness', 'cpu s', 'steps', 'rhs', 'jac', 'ncf', 'nef', 'sw', 'last', &
            'RK4 stable', 'RK4 bound', 'RK4 cpu s', 'Adams steps', 'Adams cpu s', 'Radau s', &
            'steps', 'rhs', 'max steps', 'ncf'
        do j = 1, size(kk)
            el%stiffness = kk(j)
            el%damping = zeta
            el%l0 = -1.0_dp
            call elastic_start(el, yc, y0, st)
            if (st%code /= 0) error stop 'bench_elastic: elastic start failed'
            a = elastic_atol(el, atol, rtol)
            ws = stretch_frequency(el)
            best = huge(1.0_dp)
            bestr = huge(1.0_dp)
            do rep = 1, 3
                call cpu_time(t0)
                call s%init(el, 0.0_dp, y0, rtol, a, st, tcrit=tend, method=SOLVER_LSODA)
                if (st%code == 0) call s%integrate(el, tend, y, st)
                call cpu_time(t1)
                if (st%code /= 0) error stop 'bench_elastic: integration failed'
                best = min(best, t1 - t0)
                ls = s%stats()
                call cpu_time(t0)
                call s%init(el, 0.0_dp, y0, rtol, a, st, tcrit=tend, method=SOLVER_RADAU)
                if (st%code == 0) call s%integrate(el, tend, y, st)
                call cpu_time(t1)
                if (st%code /= 0) error stop 'bench_elastic: Radau integration failed'
                bestr = min(bestr, t1 - t0)
                lr = s%stats()
            end do
            ! Radau kept in the maximal coordinates
            call s%init(el, 0.0_dp, y0, rtol, a, st, tcrit=tend, method=SOLVER_RADAU, &
                        maximal_only=.true.)
            if (st%code == 0) call s%integrate(el, tend, y, st, max_steps=5000000)
            if (st%code /= 0) error stop 'bench_elastic: Radau (maximal) integration failed'
            lm = s%stats()
            ! the non-stiff method alone: LSODA kept in Adams
            call cpu_time(t0)
            call s%init(el, 0.0_dp, y0, rtol, a, st, tcrit=tend, nonstiff_only=.true.)
            if (st%code == 0) call s%integrate(el, tend, y, st, max_steps=5000000)
            call cpu_time(t1)
            if (st%code /= 0) error stop 'bench_elastic: Adams-only integration failed'
            la = s%stats()
            adams_cpu = t1 - t0
            nrk = rk4_fewest_stable(el, y0, ceiling(tend*ws/2.8_dp), tend)
            rk_cpu = huge(1.0_dp)
            if (nrk > 0) then
                do rep = 1, 3
                    call cpu_time(t0)
                    if (.not. rk4_stable(el, y0, nrk, tend)) &
                        error stop 'bench_elastic: RK4 unstable'
                    call cpu_time(t1)
                    rk_cpu = min(rk_cpu, t1 - t0)
                end do
            end if
            write (*, '(es10.1,f9.4,i8,i9,i7,i6,i6,i6,a7,i12,i11,f11.4,i12,f12.4,f10.4,i7,i8,' // &
                   'i10,i8)') &
                kk(j), best, ls%steps, ls%rhs_evals, ls%jac_evals, ls%conv_failures, &
                ls%error_test_failures, ls%method_switches, &
                merge('BDF  ', 'Adams', ls%method_last == METHOD_BDF), nrk, &
                ceiling(tend*ws/2.8_dp), rk_cpu, la%steps, adams_cpu, bestr, lr%steps, &
                lr%rhs_evals, lm%steps, lm%conv_failures
            write (u, '(es10.3,es14.6,7i10,2i10,es14.6,2i10,es14.6,es14.6,5i10)') kk(j), best, &
                ls%steps, ls%rhs_evals, ls%jac_evals, ls%method_switches, ls%conv_failures, &
                ls%error_test_failures, merge(1, 0, ls%method_last == METHOD_BDF), nrk, &
                ceiling(tend*ws/2.8_dp), rk_cpu, la%steps, la%rhs_evals, adams_cpu, bestr, &
                lr%steps, lr%rhs_evals, lr%jac_evals, lm%steps, lm%conv_failures
        end do
        call atomic_commit(u, path, st)
    end subroutine stiffness_table

    !> Fewest RK4 steps over [0, tend] that stay stable (finite, |energy error| < 1e-3),
    !! by bisection between nb/4 and 4 nb (nb the predicted bound).
    integer function rk4_fewest_stable(el, y0, nb, tend) result(n)
        type(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y0(:), tend
        integer, intent(in) :: nb
        integer :: lo, hi, mid
        lo = max(1, nb/4)
        hi = 4*nb
        if (.not. rk4_stable(el, y0, hi, tend)) then
            n = -1
            return
        end if
        do while (hi - lo > max(1, hi/200))
            mid = (lo + hi)/2
            if (rk4_stable(el, y0, mid, tend)) then
                hi = mid
            else
                lo = mid
            end if
        end do
        n = hi
    end function rk4_fewest_stable

    logical function rk4_stable(el, y0, nsteps, tend)
        type(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y0(:), tend
        integer, intent(in) :: nsteps
        real(dp) :: ys(size(y0), 0:1)
        integer :: steps, nfe
        type(status_t) :: st
        el%mode = CABLE_AUTO
        call solve_rk4_sys(el, y0, [0.0_dp, tend], nsteps, ys, steps, nfe, st)
        rk4_stable = st%code == 0
        if (rk4_stable) rk4_stable = abs(elastic_energy(el, ys(:, 1)) - &
                                         elastic_energy(el, y0)) < 1.0e-3_dp
    end function rk4_stable

end program bench_elastic
