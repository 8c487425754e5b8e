!> Work units of the multifilar platform for the speed figures of `make bench`
!! (tests/bench/speed.sh), beside the paper's model: each mode repeats one unit n times, so
!! that one unit's instructions are the difference of two runs under callgrind (n and 0)
!! over n, its CPU time that of a run with many units over their number.
!!
!!   bench_platform rhs N            one right-hand side of the trifilar (R = 0.5, R' = 0.4,
!!                                   l = 1.2, the mass centre (0.05, 0.02) off the axis,
!!                                   0.1 below the attachments), the state moved a little
!!                                   on every call as in an integration
!!   bench_platform step N           one LSODA step (rtol 1e-10) of that trifilar released
!!                                   at 45 degrees
!!   bench_platform bifilar_step N   one LSODA step (rtol 1e-10) of the paper's model on
!!                                   input/cylinder_l180.nml from its start
!!   bench_platform elastic_step N   one Radau step (rtol 1e-10) of the quadrifilar with
!!                                   elastic cables (k = 1e6, zeta = 0.05) released at 30 deg
!!   bench_platform bifilar_elastic_step N  one Radau step (rtol 1e-10, atol 1e-12) of the
!!                                   paper's bifilar with elastic cables (k = 1e6, zeta =
!!                                   0.05) in the generalized coordinates of module
!!                                   elastic_gen, input/cylinder_l180.nml from its start
!!
!! Prints one line: `MODE units cpu_seconds_per_unit checksum`.
program bench_platform
    use kinds, only: dp, deg
    use status, only: status_t
    use bench_args, only: int_arg, need
    use deck, only: deck_t, read_deck
    use rig, only: make_pendulum, start_state
    use deck_runs, only: rig_of, start_of
    use bifilar_model, only: bifilar_t, NSTATE
    use ode_system, only: integrator_t, integrator_stats_t
    use integrators, only: new_integrator, SOLVER_LSODA, SOLVER_RADAU
    use platform_geometry, only: platform_t, regular_platform, platform_prepare
    use platform_model, only: platform_sys_t, check_platform, platform_start
    use platform_elastic, only: platform_elastic_t, pe_rest_pose, pe_start
    use elastic_model, only: elastic_t, elastic_start, ELASTIC_NSTATE
    use elastic_gen, only: elastic_gen_t, maximal_to_gen, GEN_NSTATE
    implicit none
    character(len=64) :: mode
    type(status_t) :: st
    type(platform_t) :: pl
    type(platform_sys_t) :: sys
    type(platform_elastic_t) :: el
    type(bifilar_t) :: bsys
    type(elastic_t) :: eb
    type(elastic_gen_t) :: gen
    real(dp) :: ym(ELASTIC_NSTATE), yg(GEN_NSTATE)
    type(deck_t) :: d
    type(integrator_stats_t) :: ss
    class(integrator_t), allocatable :: it
    real(dp) :: jb(3, 3), y0(6), y(6), ydot(6), yb0(NSTATE), th0(5), ye(12), qr(6), t0, t1, &
                sumck
    integer :: n, k
    call get_command_argument(1, mode)
    n = int_arg(2)
    jb = 0.0_dp
    jb(1, 1) = 0.05_dp
    jb(2, 2) = 0.06_dp
    jb(3, 3) = 0.09_dp
    pl = regular_platform(3, 0.5_dp, 0.4_dp, 1.2_dp, 1.3_dp, jb, [0.05_dp, 0.02_dp], 0.1_dp, &
                          9.81_dp)
    sumck = 0.0_dp
    select case (trim(mode))
    case ('rhs')
        call check_platform(pl, st)
        call need(st, 'bench_platform')
        sys%pl = pl
        call platform_start(pl, 30.0_dp*deg, y0, st)
        call need(st, 'bench_platform')
        y0(4:6) = [0.1_dp, -0.2_dp, 0.7_dp]
        call cpu_time(t0)
        do k = 1, n
            y = y0
            y(1) = y0(1) + 1.0e-9_dp*k
            call sys%rhs(0.0_dp, y, ydot, st)
            sumck = sumck + ydot(6)
        end do
        call cpu_time(t1)
    case ('step')
        call check_platform(pl, st)
        call need(st, 'bench_platform')
        sys%pl = pl
        call platform_start(pl, 45.0_dp*deg, y0, st)
        call need(st, 'bench_platform')
        call new_integrator(SOLVER_LSODA, it)
        call it%init(sys, 0.0_dp, y0, 1.0e-10_dp, [1.0e-12_dp], st, tcrit=1.0e6_dp)
        call need(st, 'bench_platform')
        call cpu_time(t0)
        do k = 1, n
            call it%step(sys, st, tout=1.0e6_dp)
            call need(st, 'bench_platform')
        end do
        call cpu_time(t1)
        ss = it%stats()
        sumck = ss%t_current
    case ('bifilar_step')
        call read_deck('input/cylinder_l180.nml', d, st)
        call need(st, 'bench_platform')
        call make_pendulum(rig_of(d), bsys%p, st)
        call need(st, 'bench_platform')
        call start_state(start_of(d), bsys%p, yb0, th0, st)
        call need(st, 'bench_platform')
        call new_integrator(SOLVER_LSODA, it)
        call it%init(bsys, 0.0_dp, yb0, 1.0e-10_dp, [1.0e-12_dp], st, tcrit=1.0e6_dp)
        call need(st, 'bench_platform')
        call cpu_time(t0)
        do k = 1, n
            call it%step(bsys, st, tout=1.0e6_dp)
            call need(st, 'bench_platform')
        end do
        call cpu_time(t1)
        ss = it%stats()
        sumck = ss%t_current
    case ('elastic_step')
        el%pl = regular_platform(4, 0.5_dp, 0.4_dp, 1.2_dp, 1.3_dp, jb, [0.05_dp, 0.02_dp], &
                                 0.1_dp, 9.81_dp)
        el%stiffness = 1.0e6_dp
        el%damping = 0.05_dp
        call platform_prepare(el%pl, st)
        call need(st, 'bench_platform')
        call pe_rest_pose(el, qr, st)
        call need(st, 'bench_platform')
        call pe_start(el, qr, 30.0_dp*deg, ye, st)
        call need(st, 'bench_platform')
        call new_integrator(SOLVER_RADAU, it)
        call it%init(el, 0.0_dp, ye, 1.0e-10_dp, [1.0e-12_dp], st, tcrit=1.0e6_dp)
        call need(st, 'bench_platform')
        call cpu_time(t0)
        do k = 1, n
            call it%step(el, st, tout=1.0e6_dp)
            call need(st, 'bench_platform')
        end do
        call cpu_time(t1)
        ss = it%stats()
        sumck = ss%t_current
    case ('bifilar_elastic_step')
        call read_deck('input/cylinder_l180.nml', d, st)
        call need(st, 'bench_platform')
        call make_pendulum(rig_of(d), eb%p, st)
        call need(st, 'bench_platform')
        call start_state(start_of(d), eb%p, yb0, th0, st)
        call need(st, 'bench_platform')
        eb%stiffness = 1.0e6_dp
        eb%damping = 0.05_dp
        call elastic_start(eb, yb0, ym, st)
        call need(st, 'bench_platform')
        call maximal_to_gen(eb, ym, yg, st)
        call need(st, 'bench_platform')
        gen%el = eb
        call new_integrator(SOLVER_RADAU, it)
        call it%init(gen, 0.0_dp, yg, 1.0e-10_dp, [1.0e-12_dp], st, tcrit=1.0e6_dp)
        call need(st, 'bench_platform')
        call cpu_time(t0)
        do k = 1, n
            call it%step(gen, st, tout=1.0e6_dp)
            call need(st, 'bench_platform')
        end do
        call cpu_time(t1)
        ss = it%stats()
        sumck = ss%t_current
    case default
        write (*, '(a)') 'usage: bench_platform rhs|step|bifilar_step|elastic_step|'// &
            'bifilar_elastic_step N'
        stop 1
    end select
    write (*, '(a,1x,i0,es14.5,es24.15)') trim(mode), n, (t1 - t0)/max(1, n), sumck

end program bench_platform
