!> Benchmark of the elastic-cable model (make bench): the Figs. 4-6 cylinder (l = 2 b',
!! l' = 1.8 b', raised 45 deg) with elastic cables of stiffness 1e4, 1e6, 1e8 and damping
!! ratio 0.5 over 2 torsional periods (tau = 0 ... 4 pi), LSODA at rtol 1e-8 with the
!! per-state atol of elastic_atol(1e-10): steps, right-hand sides, Jacobians, method
!! switches, CPU (best of 3), against the steps an explicit method needs (the RK4 stability
!! bound 2.8/rho, rho = omega_s of elastic_atol).  Writes the figures to the file named by
!! the first argument (default output/bench_elastic.dat).
program bench_elastic
    use kinds, only: dp, pi
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use simulate, only: make_pendulum, start_state
    use bifilar_model, only: NSTATE
    use elastic_model, only: elastic_t, elastic_start, elastic_atol, ELASTIC_NSTATE
    use lsoda, only: lsoda_t, lsoda_stats_t
    use output_io, only: atomic_open, atomic_commit
    implicit none
    real(dp), parameter :: kk(3) = [1.0e4_dp, 1.0e6_dp, 1.0e8_dp], zeta = 0.5_dp
    real(dp), parameter :: tend = 4*pi, rtol = 1.0e-8_dp, atol = 1.0e-10_dp
    type(deck_t) :: d
    type(status_t) :: st
    type(elastic_t) :: el
    type(lsoda_t) :: s
    type(lsoda_stats_t) :: ls
    real(dp) :: yc(NSTATE), th0(5), y0(ELASTIC_NSTATE), y(ELASTIC_NSTATE), a(ELASTIC_NSTATE)
    real(dp) :: best, t0, t1, ws
    character(len=1024) :: outpath
    integer :: j, rep, u
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
        'method_switches rk4_stable_steps'
    write (*, '(a)') 'elastic cables: cylinder l = 2b, l'' = 1.8b, 45 deg, damping 0.5, '// &
        'tau = 0 ... 4 pi (2 torsion periods), rtol 1e-8 (best of 3)'
    write (*, '(a10,a10,a9,a9,a7,a9,a12,a14)') 'stiffness', 'cpu s', 'steps', 'rhs', 'jac', &
        'switches', 'last method', 'RK4 steps >='
    do j = 1, size(kk)
        el%stiffness = kk(j)
        el%damping = zeta
        call elastic_start(el, yc, y0, st)
        if (st%code /= 0) error stop 'bench_elastic: elastic start failed'
        a = elastic_atol(el, atol)
        ws = a(4)/atol
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
        write (*, '(es10.1,f10.4,2i9,i7,i9,a12,i14)') kk(j), best, ls%steps, ls%rhs_evals, &
            ls%jac_evals, ls%method_switches, merge('BDF  ', 'Adams', ls%method_last == 2), &
            ceiling(tend*ws/2.8_dp)
        write (u, '(es10.3,es14.6,5i10)') kk(j), best, ls%steps, ls%rhs_evals, ls%jac_evals, &
            ls%method_switches, ceiling(tend*ws/2.8_dp)
    end do
    call atomic_commit(u, trim(outpath), st)
end program bench_elastic
