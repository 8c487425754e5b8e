!> Benchmark of the pendulum analyses (make bench): CPU time, steps and right-hand-side
!! evaluations of each paper simulation deck (best of 5 runs, files written to build/bench),
!! and the CPU time of one Floquet analysis (best of 10).  Writes the figures to the file
!! named by the first argument (default output/bench_bifilar.dat).
program bench_bifilar
    use kinds, only: dp, deg
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of
    use simulate, only: run_simulation, run_summary_t
    use rig, only: make_pendulum
    use geometry, only: pendulum_t
    use floquet, only: floquet_result_t, floquet_analysis
    use output_io, only: atomic_open, atomic_commit
    implicit none
    character(len=20), parameter :: scenes(4) = [character(len=20) :: 'cylinder_l180', &
        'cylinder_l195', 'triangle_plate', 'cylinder_torsion']
    character(len=20), parameter :: fdecks(4) = [character(len=20) :: 'cylinder_torsion', &
        'box_stable', 'box_unstable', 'box_tall_floquet']
    type(deck_t) :: d
    type(status_t) :: st
    type(run_summary_t) :: sm
    type(pendulum_t) :: p
    type(floquet_result_t) :: fr
    character(len=1024) :: outpath
    real(dp) :: best, total, t0, t1
    integer :: k, rep, u
    outpath = 'output/bench_bifilar.dat'
    if (command_argument_count() >= 1) call get_command_argument(1, outpath)
    call execute_command_line('mkdir -p build/bench')
    call atomic_open(trim(outpath), u, st)
    if (st%code /= 0) error stop 'bench_bifilar: cannot write the result file'
    write (u, '(a)') '# bifilar benchmark: paper simulation decks (rtol of each deck) and '// &
        'Floquet analyses at 45 deg, rtol 1e-10'
    write (u, '(a)') '# kind deck cpu_seconds steps rhs_evaluations'
    write (*, '(a)') 'paper simulation decks (best of 5; includes writing the output files)'
    write (*, '(a20,a14,a8,a8)') 'deck', 'cpu s', 'steps', 'rhs'
    total = 0.0_dp
    do k = 1, size(scenes)
        call read_deck('input/'//trim(scenes(k))//'.nml', d, st)
        if (st%code /= 0) error stop 'bench_bifilar: a paper deck does not read'
        best = huge(1.0_dp)
        do rep = 1, 5
            call run_simulation(d, 'build/bench', sm, st)
            best = min(best, sm%cpu_seconds)
        end do
        total = total + best
        write (*, '(a20,f14.5,2i8)') trim(scenes(k)), best, sm%steps, sm%rhs_evaluations
        write (u, '(a,1x,a,es14.6,2i9)') 'simulate', trim(scenes(k)), best, sm%steps, &
            sm%rhs_evaluations
    end do
    write (*, '(a20,f14.5,a)') 'all four', total, '   (aim: under 0.2 s)'
    write (*, '(a)') ''
    write (*, '(a)') 'Floquet analysis at 45 deg, rtol 1e-10 (best of 10)'
    write (*, '(a20,a14,a8,a8,a14)') 'deck', 'cpu ms', 'steps', 'rhs', 'max modulus'
    do k = 1, size(fdecks)
        call read_deck('input/'//trim(fdecks(k))//'.nml', d, st)
        call make_pendulum(rig_of(d), p, st)
        best = huge(1.0_dp)
        do rep = 1, 10
            call cpu_time(t0)
            call floquet_analysis(p, 45*deg, 1.0e-10_dp, 1, fr, st)
            call cpu_time(t1)
            best = min(best, t1 - t0)
        end do
        if (st%code /= 0) error stop 'bench_bifilar: a Floquet analysis failed'
        write (*, '(a20,f14.3,2i8,es14.5)') trim(fdecks(k)), 1.0e3_dp*best, fr%steps, &
            fr%rhs_evaluations, fr%max_modulus
        write (u, '(a,1x,a,es14.6,2i9)') 'floquet', trim(fdecks(k)), best, fr%steps, &
            fr%rhs_evaluations
    end do
    call atomic_commit(u, trim(outpath), st)
end program bench_bifilar
