!> Global error against rtol (make bench): for every simulation deck of the paper's
!! model in input/ and three general scenes made from input/cylinder_l180.nml (the body
!! turned 20 degrees about b1 and b2 in C, b = 1.3 b', and b = 1.3 b' released from 80
!! degrees), simulate's run (kane_run with global = .true.: LSODA at rtol/4) at
!! rtol = 1e-6 ... 1e-11 (atol = rtol/100) against LSODA at rtol/1000, but not below 3e-14,
!! the smallest it honours (atol the same over 1000), over the deck's tau_end at its output
!! times: the largest error of the four angles over the rows (rad), over rtol.  With
!! `raw` as second argument the runs are LSODA at rtol itself (no global = .true.).  Prints a table, one row per scene, and the worst
!! ratio; writes OUTFILE (default output/bench_global_error.dat).
program bench_global_error
    use kinds, only: dp, deg
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, start_of
    use geometry, only: pendulum_t
    use rig, only: rig_t, start_t, make_pendulum, start_state
    use bifilar_model, only: NSTATE
    use work_precision, only: trajectory_errors
    use kane_run, only: kane_run_t, kane_run_start
    use run_loop, only: drive
    use keep_sink, only: keep_t
    use integrators, only: SOLVER_LSODA
    implicit none

    character(len=24), parameter :: decks(5) = [character(len=24) :: 'cylinder_l180', &
        'cylinder_l195', 'cylinder_torsion', 'triangle_plate', 'work_precision_cylinder']
    character(len=24), parameter :: general(3) = [character(len=24) :: 'misaligned_body', &
        'b_ne_b_prime', 'b_ne_b_prime_80deg']
    integer, parameter :: NR = 6
    real(dp), parameter :: rtols(NR) = [1.0e-6_dp, 1.0e-7_dp, 1.0e-8_dp, 1.0e-9_dp, &
                                        1.0e-10_dp, 1.0e-11_dp]
    type(deck_t) :: d
    type(status_t) :: st
    type(rig_t) :: rg
    type(start_t) :: s0
    real(dp) :: ratio(NR), worst, c, sn
    character(len=256) :: outfile, arg
    character(len=24) :: name
    integer :: k, u
    logical :: raw
    call get_command_argument(2, arg)
    raw = trim(arg) == 'raw'
    call get_command_argument(1, outfile)
    if (len_trim(outfile) == 0) outfile = 'output/bench_global_error.dat'
    open (newunit=u, file=trim(outfile), status='replace', action='write')
    write (u, '(a)') '# global error / rtol (largest angle error over the rows, rad, against '// &
        'rtol/1000): scene then rtol = 1e-6 ... 1e-11'
    write (*, '(a)') 'global error / rtol of LSODA against rtol/1000 (largest angle error, rad)'
    write (*, '(a24,6a9)') 'scene', '1e-6', '1e-7', '1e-8', '1e-9', '1e-10', '1e-11'
    worst = 0.0_dp
    do k = 1, size(decks) + size(general)
        if (k <= size(decks)) then
            name = decks(min(k, size(decks)))
            call read_deck('input/'//trim(name)//'.nml', d, st)
        else
            name = general(max(1, k - size(decks)))
            call read_deck('input/cylinder_l180.nml', d, st)
        end if
        if (st%code /= 0) error stop 'bench_global_error: a deck does not read'
        rg = rig_of(d)
        s0 = start_of(d)
        select case (trim(name))
        case ('misaligned_body')
            ! the body's axes turned 20 deg about b1, then 20 deg about b2
            c = cos(20*deg)
            sn = sin(20*deg)
            rg%btilde = matmul(reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, c, sn, 0.0_dp, -sn, c], &
                                       [3, 3]), &
                               reshape([c, 0.0_dp, -sn, 0.0_dp, 1.0_dp, 0.0_dp, sn, 0.0_dp, c], &
                                       [3, 3]))
        case ('b_ne_b_prime')
            rg%b = 1.3_dp*rg%b_prime
        case ('b_ne_b_prime_80deg')
            rg%b = 1.3_dp*rg%b_prime
            s0%amplitude = 80.0_dp
        end select
        call scene(rg, s0, d%integration%tau_end, d%integration%dtau_out, ratio)
        worst = max(worst, maxval(ratio))
        write (*, '(a24,6f9.2)') trim(name), ratio
        write (u, '(a,6es12.4)') trim(name), ratio
    end do
    write (*, '(a,f6.2,a)') 'worst: ', worst, ' rtol'
    write (u, '(a,es12.4)') '# worst ', worst
    close (u)

contains

    !> The ratios of one scene.
    subroutine scene(r, s, tau_end, dtau, ratio)
        type(rig_t), intent(in) :: r
        type(start_t), intent(in) :: s
        real(dp), intent(in) :: tau_end, dtau
        real(dp), intent(out) :: ratio(NR)
        type(pendulum_t) :: p
        type(status_t) :: st2
        real(dp) :: y0(NSTATE), th0(5), eth, eq, ee
        real(dp), allocatable :: times(:), ys(:, :), yref(:, :)
        integer :: n, i, j
        ratio = -1.0_dp
        call make_pendulum(r, p, st2)
        if (st2%code == 0) call start_state(s, p, y0, th0, st2)
        if (st2%code /= 0) then
            write (*, '(a)') 'bench_global_error: '//st2%msg
            return
        end if
        n = nint(tau_end/dtau)
        allocate (times(0:n), ys(NSTATE, 0:n), yref(NSTATE, 0:n))
        do i = 0, n
            times(i) = dtau*i
        end do
        do j = 1, NR
            call run(p, y0, th0(3), times, max(rtols(j)/1000, 3.0e-14_dp), rtols(j)/1.0e5_dp, &
                     .false., yref, st2)
            if (st2%code /= 0) cycle
            call run(p, y0, th0(3), times, rtols(j), rtols(j)/100, .not. raw, ys, st2)
            if (st2%code /= 0) cycle
            call trajectory_errors(p, ys, yref, eth, eq, ee)
            ratio(j) = eth/rtols(j)
        end do
    end subroutine scene

    !> One run of the paper's model from y0 with the states at the times.
    subroutine run(p, y0, th3, times, rt, at, global, yout, st2)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y0(NSTATE), th3, times(0:), rt, at
        logical, intent(in) :: global
        real(dp), intent(out) :: yout(:, 0:)
        type(status_t), intent(out) :: st2
        type(kane_run_t) :: m
        type(keep_t) :: sink
        integer :: n
        n = ubound(times, 1)
        yout = 0.0_dp
        call kane_run_start(m, p, y0, th3, rt, at, SOLVER_LSODA, times(n), 'bench', st2, &
                            global=global)
        if (st2%code /= 0) return
        allocate (sink%ys(NSTATE, 0:n))
        call drive(m, times, sink, st2)
        if (st2%code /= 0) then
            write (*, '(a)') 'bench_global_error: '//st2%msg
            return
        end if
        yout = sink%ys
    end subroutine run

end program bench_global_error
