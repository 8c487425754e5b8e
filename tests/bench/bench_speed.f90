!> Work units for the speed figures of `make bench` (tests/bench/speed.sh): each mode repeats
!! one unit of work n times, so that the instruction count of one unit is the difference of
!! two runs under `valgrind --tool=callgrind` (n and 0 repetitions) divided by n, and its CPU
!! time the cpu_time of a run with many repetitions divided by their number.
!!
!!   bench_speed rhs N                one right-hand side of the paper's model (cylinder_l180
!!                                    at tau = 0, the state moved a little on every call)
!!   bench_speed floquet DECK N       one Floquet analysis of input/DECK.nml at 45 deg, rtol 1e-10
!!                                    (DECK with a / in it: that file, e.g.
!!                                    tests/bench/box_p3.nml)
!!   bench_speed chart N              one stability-chart point: the mean over the 6 x 5 grid
!!                                    l = 0.5 ... 8, amplitude 2 ... 90 deg of input/box_chart.nml
!!                                    (the box hung from its top edges), rtol 1e-8, one thread
!!   bench_speed floquet_differences DECK N, chart_differences N
!!                                    the same with the monodromy of &integration
!!                                    sensitivities = 'differences' (the variational equations
!!                                    integrated with the orbit as one system)
!!
!! Prints one line: `MODE units cpu_seconds_per_unit checksum` (the checksum keeps the work
!! from being optimised away and shows that two builds computed the same).
program bench_speed
    use kinds, only: dp, deg
    use status, only: status_t
    use bench_args, only: int_arg, need
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, start_of
    use geometry, only: pendulum_t
    use rig, only: make_pendulum, start_state
    use bifilar_model, only: bifilar_t, NSTATE
    use floquet, only: floquet_result_t, floquet_analysis
    use stability, only: set_chart_variable
    use integrators, only: SENS_FORWARD, SENS_DIFFERENCES
    implicit none
    character(len=256) :: mode, arg
    type(deck_t) :: d
    type(status_t) :: st
    type(bifilar_t) :: sys
    type(floquet_result_t) :: fr
    type(pendulum_t) :: p
    real(dp) :: y0(NSTATE), y(NSTATE), ydot(NSTATE), th0(5), t0, t1, sumck, amp
    integer :: n, k, i, j, units, sens, ls
    call get_command_argument(1, mode)
    sens = SENS_FORWARD
    ls = len_trim(mode)
    if (ls > 12) then
        if (mode(ls - 11:ls) == '_differences') then
            sens = SENS_DIFFERENCES
            mode = mode(1:ls - 12)
        end if
    end if
    sumck = 0.0_dp
    units = 0
    select case (trim(mode))
    case ('rhs')
        n = int_arg(2)
        call read_deck('input/cylinder_l180.nml', d, st)
        call need(st, 'bench_speed')
        call make_pendulum(rig_of(d), sys%p, st)
        call need(st, 'bench_speed')
        call start_state(start_of(d), sys%p, y0, th0, st)
        call need(st, 'bench_speed')
        y0(6:10) = [0.01_dp, -0.02_dp, 0.03_dp, -0.4_dp, 0.05_dp]
        call cpu_time(t0)
        do k = 1, n
            y = y0
            y(1) = y0(1) + 1.0e-9_dp*k
            call sys%rhs(0.0_dp, y, ydot, st)
            sumck = sumck + ydot(9)
        end do
        call cpu_time(t1)
        units = n
    case ('floquet')
        call get_command_argument(2, arg)
        n = int_arg(3)
        if (index(arg, '/') > 0) then
            call read_deck(trim(arg), d, st)
        else
            call read_deck('input/'//trim(arg)//'.nml', d, st)
        end if
        call need(st, 'bench_speed')
        call make_pendulum(rig_of(d), p, st)
        call need(st, 'bench_speed')
        call cpu_time(t0)
        do k = 1, n
            call floquet_analysis(p, 45*deg, 1.0e-10_dp, 1, fr, st, sensitivities=sens)
            call need(st, 'bench_speed')
            sumck = sumck + fr%max_modulus
        end do
        call cpu_time(t1)
        units = n
    case ('chart')
        n = int_arg(2)
        call read_deck('input/box_chart.nml', d, st)
        call need(st, 'bench_speed')
        call cpu_time(t0)
        do k = 1, n
            do j = 1, 5
                do i = 1, 6
                    call make_pendulum(rig_of(d), p, st)
                    amp = d%floquet%amplitude
                    call set_chart_variable('l', 0.5_dp + 1.5_dp*(i - 1), p, amp)
                    call set_chart_variable('amplitude', 2.0_dp + 22.0_dp*(j - 1), p, amp)
                    call floquet_analysis(p, amp*deg, 1.0e-8_dp, 1, fr, st, &
                                           sensitivities=sens)
                    if (st%code == 0) sumck = sumck + fr%max_modulus
                end do
            end do
        end do
        call cpu_time(t1)
        units = 30*n
    case default
        write (*, '(a)') 'usage: bench_speed rhs N | floquet[_differences] DECK N | '// &
            'chart[_differences] N'
        stop 1
    end select
    write (*, '(a,1x,i0,es14.5,es24.15)') trim(mode), units, (t1 - t0)/max(1, units), sumck

end program bench_speed
