!> bench_sweep: the cost of the points of a stability chart and a model of a chart's wall
!! time on many cores (make bench, tests/bench/mpi_scaling.sh).
!!
!!   bench_sweep DECK.nml OUT.dat [T_REQ_US [START_S]]
!!
!! Computes every point of the deck's chart on this thread alone, timing each (wall clock;
!! run it with OMP_NUM_THREADS=1 on an otherwise idle core), writes OUT.dat (`k x y
!! seconds` per point) and prints the costs' mean, spread and largest, then the model of
!! the wall time of a sweep of N points on P cores (P ranks of one thread):
!!
!!     T(P) = start + N c / P_c + c_max + N_req t_req / P_c
!!
!! c the mean cost of a point, c_max the largest (the tail: the engine's last chunks are
!! one point per thread, so the run ends at most about one point after the average core),
!! P_c the cores that compute (P while the run has at most 16 ranks, P - 1 beyond: rank 0
!! then only hands out work), N_req the requests for work (chunks: at most 64 points, and
!! about 2 P log2(N / (128 P)) + 2 P smaller ones at the end), t_req rank 0's time per
!! request (measured by the script with sweep_probe_mpi; argument T_REQ_US, default 20),
!! start the start of the ranks (START_S, default 0.3 s: mpirun -np 2 here).
!!
!! Last, the cost of checkpoints at their most frequent: a sweep of a million points that
!! cost nothing (module probe_task) without checkpoints and with `--checkpoint 0` (as often
!! as the engine's 5 % rule lets it write), and the size of the last checkpoint.
program bench_sweep
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use stability, only: chart_task, chart_task_t
    use sweep_engine, only: sweep_run, sweep_options_t, sweep_report_t
    use probe_task, only: probe_task_t
    implicit none
    type(deck_t) :: d
    type(chart_task_t) :: task
    type(status_t) :: st
    character(len=512) :: deck_path, out, arg
    real(dp), allocatable :: cost(:), sorted(:)
    real(dp) :: vals(2), mean, sd, t_req, start
    integer(int64) :: c0, c1, rate
    integer :: k, n, u, ix, iy
    integer, parameter :: NP(3) = [2, 64, 1024]
    type(probe_task_t) :: probe
    type(sweep_options_t) :: opt
    type(sweep_report_t) :: rep0, rep1
    real(dp), allocatable :: pv(:, :)
    integer(int64) :: bytes

    call get_command_argument(1, deck_path)
    call get_command_argument(2, out)
    t_req = 20.0e-6_dp
    start = 0.3_dp
    if (command_argument_count() >= 3) then
        call get_command_argument(3, arg)
        read (arg, *) t_req
        t_req = t_req*1.0e-6_dp
    end if
    if (command_argument_count() >= 4) then
        call get_command_argument(4, arg)
        read (arg, *) start
    end if
    call read_deck(trim(deck_path), d, st)
    if (st%code /= 0) error stop 'bench_sweep: cannot read the deck'
    call chart_task(d, task, st)
    if (st%code /= 0) error stop 'bench_sweep: cannot make the chart'
    n = d%chart%nx*d%chart%ny
    allocate (cost(n))
    do k = 1, n
        call system_clock(c0, rate)
        call task%compute(k, vals, st)
        call system_clock(c1)
        cost(k) = real(c1 - c0, dp)/real(rate, dp)
    end do
    open (newunit=u, file=trim(out), status='replace', action='write')
    write (u, '(a)') '# bench_sweep: wall time of each point of '//trim(deck_path)// &
        ' on one thread'
    write (u, '(a)') '# k x y seconds'
    do k = 1, n
        ix = mod(k - 1, d%chart%nx) + 1
        iy = (k - 1)/d%chart%nx + 1
        write (u, '(i0,2(1x,es14.6),1x,es12.4)') k, task%xs(ix), task%ys(iy), cost(k)
    end do
    close (u)

    sorted = cost
    call sort(sorted)
    mean = sum(cost)/n
    sd = sqrt(sum((cost - mean)**2)/(n - 1))
    write (*, '(a,i0,a)') 'points of '//trim(deck_path)//' (', n, ', one thread):'
    write (*, '(a,f8.3,a,f8.3,a,f8.3,a,f8.3,a,f8.3,a,f8.3,a)') '  cost per point: mean ', &
        1e3_dp*mean, ' ms, sd ', 1e3_dp*sd, ' ms, median ', 1e3_dp*pct(0.5_dp), &
        ' ms, 90% ', 1e3_dp*pct(0.9_dp), ' ms, 99% ', 1e3_dp*pct(0.99_dp), ' ms, max ', &
        1e3_dp*sorted(n), ' ms'
    write (*, '(a,f8.3,a,f8.3,a)') '  sum ', sum(cost), ' s; the dearest 1% of the points '// &
        'take ', 100*sum(sorted(n - n/100 + 1:n))/sum(cost), ' % of it'
    write (*, '(a,f7.1,a,f5.2,a)') 'model: T(P) = start + N c/P_c + c_max + N_req t_req/P_c '// &
        '(t_req ', 1e6_dp*t_req, ' us, start ', start, ' s)'
    write (*, '(a)') '  this chart (the sweep alone, start not counted): P = 1: '// &
        secs(model(n, 1, 0.0_dp))//', P = 2: '//secs(model(n, 2, 0.0_dp))
    write (*, '(a)') '  1000 x 1000 chart (the same region, 1e6 points), one thread per rank:'
    write (*, '(a)') '     cores  compute s     tail s   master s    start s    total'
    do k = 1, size(NP)
        write (*, '(i10,4f11.3,3x,a)') NP(k), 1.0e6_dp*mean/computing(NP(k)), sorted(n), &
            requests(1000000, NP(k))*t_req/computing(NP(k)), start, &
            secs(model(1000000, NP(k), start))
    end do

    ! checkpoints at their most frequent: a million points of no cost
    probe%n = 1000000
    probe%nap = 0
    call sweep_run(probe, 'probe', trim(deck_path), '', '', probe%n, 4, pv, st, report=rep0)
    opt%checkpoint_seconds = 0.0_dp
    call sweep_run(probe, 'probe', trim(deck_path), 'build/bench/bench_sweep.probe.partial', &
                   '', probe%n, 4, pv, st, opt, rep1)
    inquire (file='build/bench/bench_sweep.probe.partial', size=bytes)
    write (*, '(a,f6.3,a,f6.3,a,i0,a,f5.1,a)') 'checkpoints: a million points of no cost, ', &
        rep0%wall_seconds, ' s without, ', rep1%wall_seconds, ' s with --checkpoint 0 (', &
        rep1%checkpoints, ' written, the last ', real(bytes, dp)/1.0e6_dp, ' MB)'

contains

    !> Cores that compute points among P ranks of one thread.
    integer function computing(p)
        integer, intent(in) :: p
        computing = p
        if (p > 16) computing = p - 1
    end function computing

    !> Requests for work of a sweep of m points on p ranks (see the program's notes).
    real(dp) function requests(m, p)
        integer, intent(in) :: m, p
        requests = real(m, dp)/64.0_dp + 2.0_dp*p*max(0.0_dp, log(real(m, dp)/(128.0_dp*p)) &
                   /log(2.0_dp)) + 2.0_dp*p
    end function requests

    !> The model's wall time of m points on p cores.
    real(dp) function model(m, p, t0)
        integer, intent(in) :: m, p
        real(dp), intent(in) :: t0
        model = t0 + m*mean/computing(p) + sorted(n) + requests(m, p)*t_req/computing(p)
    end function model

    !> The q-quantile of the sorted costs.
    real(dp) function pct(q)
        real(dp), intent(in) :: q
        pct = sorted(max(1, min(n, nint(q*n))))
    end function pct

    !> Seconds for people: '12.3 s', '8 min 20 s'.
    function secs(t) result(s)
        real(dp), intent(in) :: t
        character(len=:), allocatable :: s
        character(len=32) :: buf
        if (t < 120.0_dp) then
            write (buf, '(f0.2,a)') t, ' s'
        else
            write (buf, '(i0,a,i0,a)') int(t)/60, ' min ', mod(int(t), 60), ' s'
        end if
        s = trim(buf)
        if (s(1:1) == '.') s = '0'//s
    end function secs

    !> Sort ascending (insertion sort: a few thousand values).
    subroutine sort(a)
        real(dp), intent(inout) :: a(:)
        integer :: i, j
        real(dp) :: x
        do i = 2, size(a)
            x = a(i)
            j = i - 1
            do while (j >= 1)
                if (a(j) <= x) exit
                a(j + 1) = a(j)
                j = j - 1
            end do
            a(j + 1) = x
        end do
    end subroutine sort

end program bench_sweep
