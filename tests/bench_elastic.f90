!> Benchmark of the elastic-cable model (make bench): the Figs. 4-6 cylinder (l = 2 b',
!! l' = 1.8 b', raised 45 deg) with elastic cables of stiffness 1e4, 1e6, 1e8 and damping
!! ratio 0.5 over 2 torsional periods (tau = 0 ... 4 pi).  LSODA with the cables' modes
!! (elastic_solver) at rtol 1e-8 with the per-state atol of elastic_atol(1e-10, 1e-8): steps,
!! right-hand sides, Jacobians, convergence and error-test failures, CPU (best of 3).
!! Against it, fixed-step classical RK4 on the same equations: the fewest steps with which it
!! stays stable over the same interval (|energy error| < 1e-3 at the end), found by
!! bisection over the number of steps; the bound 2.8/rho that its stability region predicts
!! (rho = omega_s, stretch_frequency); and its CPU at the fewest stable steps (best of 3).
!! And the non-stiff method with error control: the same LSODA kept in Adams
!! (nonstiff_only), its steps, right-hand sides and CPU (one run).
!! Writes the figures to the file named by the first argument (default
!! output/bench_elastic.dat).
program bench_elastic
    use kinds, only: dp, pi
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use simulate, only: make_pendulum, start_state
    use bifilar_model, only: NSTATE
    use elastic_model, only: elastic_t, elastic_start, elastic_atol, elastic_energy, &
                             stretch_frequency, ELASTIC_NSTATE, CABLE_AUTO
    use elastic_solver, only: elastic_solver_t
    use lsoda, only: lsoda_stats_t, METHOD_BDF
    use work_precision, only: solve_rk4_sys
    use output_io, only: atomic_open, atomic_commit
    implicit none
    real(dp), parameter :: kk(3) = [1.0e4_dp, 1.0e6_dp, 1.0e8_dp], zeta = 0.5_dp
    real(dp), parameter :: tend = 4*pi, rtol = 1.0e-8_dp, atol = 1.0e-10_dp
    type(deck_t) :: d
    type(status_t) :: st
    type(elastic_t) :: el
    type(elastic_solver_t) :: s
    type(lsoda_stats_t) :: ls, la
    real(dp) :: yc(NSTATE), th0(5), y0(ELASTIC_NSTATE), y(ELASTIC_NSTATE), a(ELASTIC_NSTATE)
    real(dp) :: best, t0, t1, ws, rk_cpu, adams_cpu
    character(len=1024) :: outpath
    integer :: j, rep, u, nrk
    outpath = 'output/bench_elastic.dat'
    if (command_argument_count() >= 1) call get_command_argument(1, outpath)
    call read_deck('input/cylinder_l180.nml', d, st)
    if (st%code /= 0) error stop 'bench_elastic: input/cylinder_l180.nml does not read'
    call make_pendulum(d, el%p, st)
    call start_state(d, el%p, yc, th0, st)
    if (st%code /= 0) error stop 'bench_elastic: no start'
    call atomic_open(trim(outpath), u, st)
    if (st%code /= 0) error stop 'bench_elastic: cannot write the result file'
    write (u, '(a)') '# bifilar benchmark: elastic cables, cylinder l = 2b, l'' = 1.8b, '// &
        '45 deg, damping 0.5, tau = 0 ... 4 pi, rtol 1e-8'
    write (u, '(a)') '# stiffness cpu_seconds steps rhs_evaluations jacobian_evaluations '// &
        'method_switches conv_failures error_test_failures last_method_bdf '// &
        'rk4_fewest_stable_steps rk4_bound_steps rk4_cpu_seconds adams_only_steps '// &
        'adams_only_rhs_evaluations adams_only_cpu_seconds'
    write (*, '(a)') 'elastic cables: cylinder l = 2b, l'' = 1.8b, 45 deg, damping 0.5, '// &
        'tau = 0 ... 4 pi (2 torsion periods), rtol 1e-8 (best of 3)'
    write (*, '(a10,a9,a8,a9,a7,a6,a6,a6,a7,a12,a11,a11,a12,a12)') 'stiffness', 'cpu s', &
        'steps', 'rhs', 'jac', 'ncf', 'nef', 'sw', 'last', 'RK4 stable', 'RK4 bound', &
        'RK4 cpu s', 'Adams steps', 'Adams cpu s'
    do j = 1, size(kk)
        el%stiffness = kk(j)
        el%damping = zeta
        el%l0 = -1.0_dp
        call elastic_start(el, yc, y0, st)
        if (st%code /= 0) error stop 'bench_elastic: elastic start failed'
        a = elastic_atol(el, atol, rtol)
        ws = stretch_frequency(el)
        best = huge(1.0_dp)
        do rep = 1, 3
            call cpu_time(t0)
            call s%init(el, 0.0_dp, y0, rtol, a, st, tcrit=tend)
            if (st%code == 0) call s%integrate(el, tend, y, st)
            call cpu_time(t1)
            if (st%code /= 0) error stop 'bench_elastic: integration failed'
            best = min(best, t1 - t0)
        end do
        ls = s%stats()
        ! the non-stiff method alone: LSODA kept in Adams
        call cpu_time(t0)
        call s%init(el, 0.0_dp, y0, rtol, a, st, tcrit=tend, nonstiff_only=.true.)
        if (st%code == 0) call s%integrate(el, tend, y, st, max_steps=5000000)
        call cpu_time(t1)
        if (st%code /= 0) error stop 'bench_elastic: Adams-only integration failed'
        la = s%stats()
        adams_cpu = t1 - t0
        nrk = rk4_fewest_stable(el, y0, ceiling(tend*ws/2.8_dp))
        rk_cpu = huge(1.0_dp)
        if (nrk > 0) then
            do rep = 1, 3
                call cpu_time(t0)
                if (.not. rk4_stable(el, y0, nrk)) error stop 'bench_elastic: RK4 unstable'
                call cpu_time(t1)
                rk_cpu = min(rk_cpu, t1 - t0)
            end do
        end if
        write (*, '(es10.1,f9.4,i8,i9,i7,i6,i6,i6,a7,i12,i11,f11.4,i12,f12.4)') kk(j), best, &
            ls%steps, ls%rhs_evals, ls%jac_evals, ls%conv_failures, ls%error_test_failures, &
            ls%method_switches, merge('BDF  ', 'Adams', ls%method_last == METHOD_BDF), nrk, &
            ceiling(tend*ws/2.8_dp), rk_cpu, la%steps, adams_cpu
        write (u, '(es10.3,es14.6,7i10,2i10,es14.6,2i10,es14.6)') kk(j), best, ls%steps, &
            ls%rhs_evals, ls%jac_evals, ls%method_switches, ls%conv_failures, &
            ls%error_test_failures, merge(1, 0, ls%method_last == METHOD_BDF), nrk, &
            ceiling(tend*ws/2.8_dp), rk_cpu, la%steps, la%rhs_evals, adams_cpu
    end do
    call atomic_commit(u, trim(outpath), st)

contains

    !> Fewest RK4 steps over [0, tend] that stay stable (finite, |energy error| < 1e-3),
    !! by bisection between nb/4 and 4 nb (nb the predicted bound).
    integer function rk4_fewest_stable(el, y0, nb) result(n)
        type(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y0(:)
        integer, intent(in) :: nb
        integer :: lo, hi, mid
        lo = max(1, nb/4)
        hi = 4*nb
        if (.not. rk4_stable(el, y0, hi)) then
            n = -1
            return
        end if
        do while (hi - lo > max(1, hi/200))
            mid = (lo + hi)/2
            if (rk4_stable(el, y0, mid)) then
                hi = mid
            else
                lo = mid
            end if
        end do
        n = hi
    end function rk4_fewest_stable

    logical function rk4_stable(el, y0, nsteps)
        type(elastic_t), intent(inout) :: el
        real(dp), intent(in) :: y0(:)
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
