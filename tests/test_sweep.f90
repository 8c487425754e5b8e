!> Sweeps over threads and ranks, checkpoints and resuming: the engine in
!! process with a task of known values (module probe_task), the stability chart, a design
!! and identify's Monte Carlo through bin/bifilar killed and resumed, and, when OpenMPI is
!! installed, bin/bifilar_mpi and sweep_probe_mpi under mpirun with 1, 2 and 3 ranks, a
!! rank killed mid-sweep, ranks that see another deck or record and points that fail.
module test_sweep
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use testing, only: tester_t, write_text, exists, file_has, count_lines, line_starts, &
                       first_line, run, shell_count, msg_of, scratch_dir, fresh_dir, empty_dir, &
                       abs_path, seal_records
    use status, only: status_t, STATUS_OK, ERR_NUMERIC
    use text, only: itoa
    use sweep_engine, only: sweep_run, sweep_options_t, sweep_report_t
    use crc64, only: crc64_of
    use probe_task, only: probe_task_t, special_value
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, start_of, accuracy_of
    use period_inversion, only: input_u_t, period_fit_t, invert_periods, period_mc_sample
    use record_fit, only: make_record
    !$ use omp_lib, only: omp_get_max_threads, omp_set_num_threads
    implicit none
    private

    public :: run_sweep_tests

    character(len=*), parameter :: SCR = 'build/test_sweep'
    character, parameter :: NL = new_line('a')
    !> mpirun as the tests run it: as root too, more ranks than cores, no notes of its own.
    character(len=*), parameter :: MPIENV = 'env OMPI_ALLOW_RUN_AS_ROOT=1 '// &
        'OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1'
    character(len=*), parameter :: MPIRUN = MPIENV//' OMP_NUM_THREADS=1 mpirun -q --oversubscribe'
    !> The same for runs that end with an error: mpirun then waits odls_base_sigkill_timeout
    !! (1 s) and more before it ends; 0 saves that (not for a killed rank: rank 0 needs the
    !! time between SIGTERM and SIGKILL to say what happened).
    character(len=*), parameter :: MPIFAIL = MPIENV//' OMPI_MCA_odls_base_sigkill_timeout=0 '// &
        'OMP_NUM_THREADS=1 mpirun -q --oversubscribe'
    !> For a rank killed on purpose: mpirun sends SIGCONT, waits odls_base_sigkill_timeout,
    !! sends SIGTERM, waits again and sends SIGKILL.  Its wait is sleep(3) on whole seconds,
    !! cut short by the SIGCHLD of a rank that dies, and rounded: with the default 1 s the
    !! SIGKILL may follow the SIGTERM at once on a loaded machine, before rank 0 has said
    !! anything (tests/bench/kill_window.sh, two cores shared with six busy processes: no
    !! line in 3 of 100 runs with 1 s).  3 s leaves rank 0 its time (doc/parallel.md).
    character(len=*), parameter :: MPIKILL = MPIENV//' OMPI_MCA_odls_base_sigkill_timeout=3 '// &
        'OMP_NUM_THREADS=1 mpirun -q --oversubscribe'
    !> The parallelepiped of input/box_chart.nml (stable and unstable points, cheap ones and
    !! dear ones); the chart's grid is added per test.
    character(len=*), parameter :: BOX = &
        "&scene title = 'sweep test chart', analyses = 'chart' /"//NL// &
        '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 2.0, g = 1.0 /'//NL// &
        '&body mass = 1.0, inertia = 0.08854166666666667, 1.416666666666667, '// &
        '1.338541666666667,'//NL// &
        '      r = 2.06155281280883, lambda = 1.325817663668033, sway_depth = 4 /'//NL// &
        '&floquet amplitude = 45.0, segments = 1, rtol = 1e-6 /'//NL
    !> The block of input/box_design.nml (SI units) for a rig design; its &design per test.
    character(len=*), parameter :: RIG = &
        "&scene title = 'sweep test design', analyses = 'design' /"//NL// &
        '&suspension b = 0.2, b_prime = 0.2, l = 0.6, l_prime = 0.6, g = 9.80665 /'//NL// &
        '&body mass = 2.0, inertia = 0.007083333333333333, 0.11333333333333333, '// &
        '0.10708333333333333,'//NL// &
        '      r = 0.412310562561766, lambda = 1.325817663668033, sway_depth = 0.8 /'//NL// &
        '&floquet rtol = 1e-6 /'//NL
    !> The laboratory rig of input/identify_periods.nml with its three periods; the number
    !! of Monte Carlo samples (and the seed) per test, then ' /'.
    character(len=*), parameter :: PERIODS = &
        "&scene title = 'sweep test identify', analyses = 'identify' /"//NL// &
        '&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.20, g = 9.80665 /'//NL// &
        '&body mass = 3.10, inertia = 0.045, 0.0630, 0.0304, r = 0.25, '// &
        'lambda = 0.6435011087932844, sway_depth = 0.30 /'//NL// &
        '&measurement periods = 1.41564, 1.44107, 1.52913, amplitudes = 10.0, 30.0, 60.0,'// &
        NL//'      u_mass = 0.001, u_l = 0.001, u_l_prime = 0.001, u_b = 0.0005, '// &
        'u_b_prime = 0.0005,'//NL//'      u_period = 1e-4, u_amplitude = 0.5, '
    !> That rig with a period of 0.065 s timed to 0.0125 s (its 5-sigma range inside
    !! periods > 0, as the deck reader requires): some Monte Carlo samples draw a period
    !! below the shortest any positive I1 gives (0.04 s), and fail.  I2 = I3 (a body that
    !! may have so small an I1: a rod along b1).
    character(len=*), parameter :: BADMC = "&scene title = 'sweep test identify', "// &
        "analyses = 'identify' /"//NL// &
        '&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.20, g = 9.80665 /'//NL// &
        '&body mass = 3.10, inertia = 0.0005, 0.0304, 0.0304, r = 0.25, '// &
        'lambda = 0.6435011087932844, sway_depth = 0.30 /'//NL// &
        '&measurement periods = 0.065, amplitudes = 10.0, u_period = 0.0125, '// &
        'monte_carlo = 50 /'//NL

contains

    subroutine run_sweep_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCR)
        if (t%want('sweep: CRC-64 of the fingerprints')) call test_crc(t)
        if (t%want('sweep: engine: values in index order over threads')) call test_order(t)
        if (t%want('sweep: engine: a failing point ends the sweep')) call test_failure(t)
        if (t%want('sweep: engine: checkpoints keep every bit, resume only their own sweep')) &
            call test_checkpoints(t)
        if (t%want('sweep: chart killed after a checkpoint, resumed: the same file')) &
            call test_kill_resume(t, exe)
        if (t%want('sweep: design killed after a checkpoint, resumed: the same file')) &
            call test_design_resume(t, exe)
        if (t%want('sweep: identify Monte Carlo killed after a checkpoint, resumed: the '// &
                   'same file')) call test_mc_resume(t, exe)
        if (t%want('sweep: identify Monte Carlo: the first failed sample ends it')) &
            call test_mc_failure(t, exe)
        if (t%want('sweep mpi: charts and designs on 1, 2, 3 ranks, killed ranks, other '// &
                   'decks, failures')) &
            call test_mpi(t, exe)
        if (t%want('sweep mpi: identify Monte Carlo of periods on 1, 2, 3 ranks, of a '// &
                   'record on 2, 3, rank 0 computing none, another record, a failed sample')) &
            call test_mpi_mc(t, exe)
    end subroutine run_sweep_tests

    ! ---------------------------------------------------------------------------------------
    !> CRC-64/XZ's published check value, and a CRC continued over two pieces.
    subroutine test_crc(t)
        type(tester_t), intent(inout) :: t
        integer(int64) :: want
        want = ior(ishft(int(z'995DC9BB', int64), 32), int(z'DF1939FA', int64))
        call t%check('crc64("123456789") = 995DC9BBDF1939FA (CRC-64/XZ check value)', &
                     crc64_of('123456789') == want)
        call t%check('crc64 continued over two pieces = crc64 of the whole', &
                     crc64_of('6789', crc64_of('12345')) == want)
        call t%check('crc64 of one changed byte differs', crc64_of('123456788') /= want)
    end subroutine test_crc

    ! ---------------------------------------------------------------------------------------
    !> Point i's values land in column i whatever thread computes it, with 1 and 3 threads.
    subroutine test_order(t)
        type(tester_t), intent(inout) :: t
        type(probe_task_t) :: task
        type(sweep_report_t) :: rep
        type(status_t) :: st
        real(dp), allocatable :: v(:, :)
        integer :: nt, keep, i
        character(len=:), allocatable :: fp
        fp = SCR//'/order.fp'
        call write_text(fp, 'order')
        allocate (v(4, 0))              ! sweep_run reallocates it (gcc -flto warned otherwise)
        keep = 1
        !$ keep = omp_get_max_threads()
        do nt = 1, 3, 2
            !$ call omp_set_num_threads(nt)
            task%n = 500
            task%nap = 20
            call sweep_run(task, 'probe', fp, '', '', task%n, 4, v, st, report=rep)
            call t%check('order: '//itoa(nt)//' threads: status ok', st%code == STATUS_OK)
            if (st%code /= STATUS_OK .or. .not. allocated(v)) cycle
            call t%check('order: '//itoa(nt)//' threads: point i in column i, exactly', &
                         all([(v(1, i) == real(i, dp) .and. v(2, i) == sqrt(real(i, dp)), &
                         i=1, task%n)]))
            !$ call t%check('order: computed by '//itoa(nt)//' threads', all(v(4, :) == nt))
            call t%check('order: one rank, no checkpoint', rep%ranks == 1 .and. &
                         rep%checkpoints == 0 .and. rep%resumed == 0)
        end do
        !$ call omp_set_num_threads(keep)
    end subroutine test_order

    ! ---------------------------------------------------------------------------------------
    !> A point whose compute fails ends the sweep with its status and message; its
    !! checkpoint (from an earlier run) is removed.
    subroutine test_failure(t)
        type(tester_t), intent(inout) :: t
        type(probe_task_t) :: task
        type(sweep_options_t) :: opt
        type(status_t) :: st
        real(dp), allocatable :: v(:, :)
        character(len=:), allocatable :: fp, ck
        fp = SCR//'/failure.fp'
        ck = SCR//'/failure.probe.partial'
        call write_text(fp, 'failure')
        call execute_command_line('rm -f '//ck)
        opt%checkpoint_seconds = 0.0_dp
        task%n = 200
        task%nap = 0
        call sweep_run(task, 'probe', fp, ck, '', task%n, 4, v, st, opt)
        call t%check('failure: a good run leaves its checkpoint', all([st%code == STATUS_OK, &
                     exists(ck)]))
        task%mode = 'fail_at'
        task%at = 137
        call sweep_run(task, 'probe', fp, ck, '', task%n, 4, v, st, opt)
        call t%check('failure: the point''s status', st%code == ERR_NUMERIC)
        call t%check('failure: the point''s message', &
                     index(msg_of(st), 'probe point 137 failed') > 0)
        call t%check('failure: no values', .not. allocated(v))
        call t%check('failure: the checkpoint is removed', .not. exists(ck))
    end subroutine test_failure

    ! ---------------------------------------------------------------------------------------
    !> A checkpoint holds every bit of every value (-0, subnormals, huge, Inf, NaN), a resume
    !! takes the points of a checkpoint of its own sweep and computes the rest, and a
    !! checkpoint of another deck, analysis or size, or a damaged one, is not used.
    subroutine test_checkpoints(t)
        type(tester_t), intent(inout) :: t
        type(probe_task_t) :: task
        type(sweep_options_t) :: opt
        type(sweep_report_t) :: rep
        type(status_t) :: st
        real(dp), allocatable :: v(:, :)
        character(len=:), allocatable :: fp, ck
        integer :: i, k
        logical :: same
        fp = SCR//'/ckpt.fp'
        ck = SCR//'/ckpt.probe.partial'
        call write_text(fp, 'checkpoint deck 1')
        call execute_command_line('rm -f '//ck)
        opt%checkpoint_seconds = 0.0_dp
        task%n = 64
        task%nap = 0
        task%mode = 'special'
        call sweep_run(task, 'probe', fp, ck, '', task%n, 4, v, st, opt, rep)
        call t%check('checkpoint: written', all([st%code == STATUS_OK, exists(ck), &
                     rep%checkpoints > 0]))
        ! resume with a task that would give other values: every point from the checkpoint
        task%mode = 'ok'
        opt%resume = .true.
        call sweep_run(task, 'probe', fp, ck, '', task%n, 4, v, st, opt, rep)
        call t%check('checkpoint: resume takes all 64 points', st%code == STATUS_OK .and. &
                     rep%resumed == 64 .and. len(rep%note) == 0)
        if (st%code == STATUS_OK) then
            same = .true.
            do i = 1, task%n
                do k = 1, 4
                    if (transfer(v(k, i), 0_int64) /= transfer(special_value(i + k - 1), &
                                                               0_int64)) same = .false.
                end do
            end do
            call t%check('checkpoint: every bit of -0, subnormal, huge, 1+eps, pi, 1/3, '// &
                         'Inf, NaN kept', same)
        end if
        ! keep the first 20 points of a checkpoint of values shifted by 0.5: a resume
        ! takes those 20 and computes the other 44
        task%shift = 0.5_dp
        opt%resume = .false.
        call sweep_run(task, 'probe', fp, ck, '', task%n, 4, v, st, opt, rep)
        call execute_command_line('awk ''BEGIN{n=-1} /^done /{print "done 20"; n=0; next} '// &
            'n>=0 && n<20 {print; n++; next} n>=20 && !/^end/ {next} {print}'' '//ck// &
            ' > '//ck//'.cut && mv '//ck//'.cut '//ck)
        task%shift = 0.0_dp
        opt%resume = .true.
        call sweep_run(task, 'probe', fp, ck, '', task%n, 4, v, st, opt, rep)
        call t%check('checkpoint: 20 of 64 points resumed', st%code == STATUS_OK .and. &
                     rep%resumed == 20)
        if (st%code == STATUS_OK) call t%check('checkpoint: the 20 from it, 44 computed', &
            all([(v(1, i) == real(i, dp) + merge(0.5_dp, 0.0_dp, i <= 20), i=1, task%n)]))
        ! not its own: another deck, another analysis, another size, damaged
        call sweep_run(task, 'probe', fp, ck, '', task%n, 4, v, st, opt, rep)   ! a full one
        call write_text(fp, 'checkpoint deck 2')
        call stale(fp, ck, 'another deck', 'probe', task%n, 'another deck')
        call write_text(fp, 'checkpoint deck 1')
        call stale(fp, ck, 'another analysis', 'probe2', task%n, 'another analysis')
        call stale(fp, ck, 'another size', 'probe', task%n + 1, 'number of points')
        call execute_command_line('cp '//ck//' '//ck//'.full')
        ! a record damaged: that point alone is computed again, the others are taken
        call execute_command_line('sed -i "s/^5 4/5 G/" '//ck)
        call partly(fp, ck, .false., 'a damaged record', 5)
        ! one hexadecimal digit flipped: its checksum fails
        call execute_command_line('cp '//ck//'.full '//ck//' && sed -i "s/^9 40/9 50/" '//ck)
        call partly(fp, ck, .false., 'a flipped digit', 9)
        ! a value changed and its record sealed again: taken, unless the task refuses it
        call execute_command_line('cp '//ck//'.full '//ck//' && sed -i "s/^7 \([0-9A-F]*\)'// &
            ' [0-9A-F]*/7 \1 0000000000000000/" '//ck)
        call seal_records(ck)
        call partly(fp, ck, .true., 'a value out of range, sealed', 7)
        ! the header damaged: nothing is taken
        call execute_command_line('cp '//ck//'.full '//ck//' && sed -i "s/^done 64/done x/" '//ck)
        call stale(fp, ck, 'a damaged header', 'probe', task%n, 'damaged')
        call execute_command_line('rm -f '//ck//' '//ck//'.full')
        call stale(fp, ck, 'no checkpoint', 'probe', task%n, 'no checkpoint')

    contains

        !> A resume with this checkpoint takes every point but `bad`, which it computes again
        !! (a strict task: one that checks its values).
        subroutine partly(fp, ck, strict, what, bad)
            character(len=*), intent(in) :: fp, ck      !! fingerprint file, checkpoint
            logical, intent(in) :: strict
            character(len=*), intent(in) :: what
            integer, intent(in) :: bad
            type(probe_task_t) :: tk
            type(sweep_options_t) :: o
            o%resume = .true.
            o%checkpoint_seconds = 1.0e6_dp
            tk%n = task%n
            tk%nap = 0
            tk%shift = 0.25_dp
            tk%strict = strict
            call sweep_run(tk, 'probe', fp, ck, '', tk%n, 4, v, st, o, rep)
            call t%check('checkpoint: '//what//': '//itoa(tk%n - 1)//' resumed, 1 computed '// &
                'again (resumed '//itoa(rep%resumed)//', rejected '//itoa(rep%rejected)//')', &
                st%code == STATUS_OK .and. rep%resumed == tk%n - 1 .and. rep%rejected == 1 &
                .and. len(rep%note) == 0)
            if (st%code == STATUS_OK) call t%check('checkpoint: '//what//': point '// &
                itoa(bad)//' computed, the others from the checkpoint', &
                all([(v(1, i) == real(i, dp) + merge(0.25_dp, merge(0.5_dp, 0.0_dp, i <= 20), &
                i == bad), i=1, tk%n)]))
        end subroutine partly

        !> A resume with this checkpoint computes every point and says why.
        subroutine stale(fp, ck, what, analysis, n, why)
            character(len=*), intent(in) :: fp, ck      !! fingerprint file, checkpoint
            character(len=*), intent(in) :: what, analysis, why
            integer, intent(in) :: n
            type(probe_task_t) :: tk
            type(sweep_options_t) :: o
            o%resume = .true.
            o%checkpoint_seconds = 1.0e6_dp         ! writes none: the checkpoint stays
            tk%n = n
            tk%nap = 0
            tk%shift = 0.25_dp
            call sweep_run(tk, analysis, fp, ck, '', tk%n, 4, v, st, o, rep)
            call t%check('checkpoint: '//what//': nothing resumed ('//rep%note//')', &
                         st%code == STATUS_OK .and. rep%resumed == 0 .and. &
                         index(rep%note, why) > 0)
            if (st%code == STATUS_OK) call t%check('checkpoint: '//what//': all computed', &
                all([(v(1, i) == real(i, dp) + 0.25_dp, i=1, n)]))
        end subroutine stale

    end subroutine test_checkpoints

    ! ---------------------------------------------------------------------------------------
    !> The chart through bin/bifilar: killed (SIGKILL) after its first checkpoint and resumed,
    !! the same file as an uninterrupted run; SIGTERM: one line naming the deck, no file but
    !! the checkpoint; the checkpoint of another deck of the same name is not used.
    subroutine test_kill_resume(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, deck, ck, ref, dat
        integer :: ex, nres
        d = SCR//'/sweep_kill'
        call fresh_dir(d)
        deck = d//'/kchart.nml'
        call write_text(deck, BOX//"&chart x = 'l', x_min = 0.5, x_max = 8.0, nx = 24, "// &
                        "y = 'amplitude', y_min = 2.0, y_max = 90.0, ny = 16 /"//NL)
        ref = d//'/ref/kchart.chart.dat'
        dat = d//'/out/kchart.chart.dat'
        ck = d//'/out/kchart.chart.partial'
        ex = run(exe//' '//deck//' --out '//d//'/ref', d)
        call t%check('kill: the uninterrupted chart (exit 0)', all([ex == 0, exists(ref)]))
        ex = run('tests/tools/kill_run.sh '//ck//' KILL '//exe//' '//deck//' --out '//d// &
                 '/out --checkpoint 0', d)
        call t%check('kill: killed after its first checkpoint (exit 137, got '//itoa(ex)//')', &
                     ex == 137)
        call t%check('kill: the checkpoint is there, the chart is not', all([exists(ck), &
                     .not. exists(dat)]))
        call execute_command_line('cp '//ck//' '//d//'/kept.partial')
        ex = run(exe//' '//deck//' --out '//d//'/out --resume', d)
        nres = resumed(d//'/stdout')
        call t%check('kill: resumed (exit 0, '//itoa(nres)//' of 384 points from the '// &
                     'checkpoint)', ex == 0 .and. nres > 0 .and. nres < 384)
        call t%check('kill: resumed file = uninterrupted file, byte for byte', same_file(dat, ref))
        call t%check('kill: the checkpoint is removed with the commit', .not. exists(ck))

        ! SIGTERM during the sweep: one line, nothing but the checkpoint
        call execute_command_line('rm -rf '//d//'/out')
        ex = run('tests/tools/kill_run.sh '//ck//' TERM '//exe//' '//deck//' --out '//d// &
                 '/out --checkpoint 0', d)
        call t%check('term: exit 143 (128 + SIGTERM; got '//itoa(ex)//')', ex == 143)
        call t%check('term: one stderr line naming the deck and the checkpoint', &
                     all([count_lines(d//'/stderr') == 1, line_starts(d//'/stderr', 1, &
                     'bifilar: error (interrupted): '//deck//': chart stopped by signal 15'), &
                     file_has(d//'/stderr', ck//': run again with --resume')]))
        call t%check('term: only the checkpoint is left', all([exists(ck), &
                     shell_count('ls -A '//d//'/out | wc -l', d) == 1]))

        ! another deck named kchart.nml (the same number of points over another range of l)
        ! with the kept checkpoint: not used, for its CRC-64 (a smaller grid would refuse a
        ! checkpoint that holds more points than it has first, which depends on how far the
        ! killed chart had come)
        call execute_command_line('mkdir -p '//d//'/o '//d//'/other && cp '//d// &
                                  '/kept.partial '//d//'/other/kchart.chart.partial')
        call write_text(d//'/o/kchart.nml', BOX//"&chart x = 'l', x_min = 0.5, x_max = 7.0, "// &
                        "nx = 24, y = 'amplitude', y_min = 2.0, y_max = 90.0, ny = 16 /"//NL)
        ex = run(exe//' '//d//'/o/kchart.nml --out '//d//'/o', d)
        ex = run(exe//' '//d//'/o/kchart.nml --out '//d//'/other --resume', d)
        call t%check('stale: another deck''s checkpoint is not used (exit 0, no point '// &
                     'resumed, says why)', all([ex == 0, resumed(d//'/stdout') == 0, &
                     file_has(d//'/stdout', 'another deck (its CRC-64 differs): computed afresh')]))
        call t%check('stale: the file is that of a fresh run', same_file(d// &
                     '/other/kchart.chart.dat', d//'/o/kchart.chart.dat'))
        ! the kept checkpoint of kchart.nml with its first value made 100 (a modulus a point
        ! could have) and its record's checksum made anew: used (100 shows)
        call execute_command_line('cp '//d//'/kept.partial '//d//'/other/kchart.chart.partial'// &
            ' && sed -i "/^done/{n;s/ [0-9A-F]\{16\}/ 4059000000000000/}" '//d// &
            '/other/kchart.chart.partial')
        call seal_records(d//'/other/kchart.chart.partial')
        ex = run(exe//' '//deck//' --out '//d//'/other --resume', d)
        call t%check('stale: its own deck''s checkpoint is used (the tampered 100 shows)', &
                     all([ex == 0, resumed(d//'/stdout') > 0, &
                     file_has(d//'/other/kchart.chart.dat', '1.000000000000000E+002')]))
        ! without --resume the same checkpoint is ignored, and gone after the commit
        call execute_command_line('cp '//d//'/kept.partial '//d//'/other/kchart.chart.partial'// &
            ' && sed -i "/^done/{n;s/ [0-9A-F]\{16\}/ 4059000000000000/}" '//d// &
            '/other/kchart.chart.partial')
        ex = run(exe//' '//deck//' --out '//d//'/other', d)
        call t%check('no --resume: the checkpoint is ignored (the uninterrupted file)', &
                     all([ex == 0, resumed(d//'/stdout') == 0, .not. file_has(d//'/stdout', &
                     'checkpoint'), same_file(d//'/other/kchart.chart.dat', ref)]))
        call t%check('no --resume: the checkpoint is gone after the commit', &
                     .not. exists(d//'/other/kchart.chart.partial'))
    end subroutine test_kill_resume

    ! ---------------------------------------------------------------------------------------
    !> A rig design (three sweeps) through bin/bifilar killed (SIGKILL) after the first
    !! checkpoint of its grid's sweep and resumed: the uninterrupted file; the checkpoints
    !! are removed with the commit.
    subroutine test_design_resume(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, deck
        integer :: ex, nres
        d = SCR//'/sweep_design'
        call fresh_dir(d)
        deck = d//'/rig.nml'
        call write_text(deck, RIG//'&design l_min = 0.1, l_max = 1.2, nl = 30, '// &
                        'amplitude_max = 50, n_amplitudes = 6 /'//NL)
        ex = run(exe//' '//deck//' --out '//d//'/ref', d)
        call t%check('design kill: the uninterrupted design (exit 0)', all([ex == 0, &
                     exists(d//'/ref/rig.design')]))
        ex = run('tests/tools/kill_run.sh '//d//'/out/rig.design.partial KILL '//exe//' '//deck// &
                 ' --out '//d//'/out --checkpoint 0', d)
        call t%check('design kill: killed after the first checkpoint (exit 137, got '// &
                     itoa(ex)//')', all([ex == 137, .not. exists(d//'/out/rig.design')]))
        ex = run(exe//' '//deck//' --out '//d//'/out --resume', d)
        nres = resumed(d//'/stdout')
        call t%check('design kill: resumed (exit 0, '//itoa(nres)//' points from the '// &
                     'checkpoint)', all([ex == 0, nres > 0]))
        call t%check('design kill: resumed file = uninterrupted file, byte for byte', &
                     same_file(d//'/out/rig.design', d//'/ref/rig.design'))
        ! (SIGKILL may land while a checkpoint is written: its NAME.*.partial.tmp.PID.N stays,
        ! as doc/parallel.md says of SIGKILL; the checkpoints themselves must be gone)
        call t%check('design kill: its checkpoints are removed with the commit', &
                     shell_count('ls '//d//'/out | grep -c ''\.partial$''', d) == 0)
    end subroutine test_design_resume

    ! ---------------------------------------------------------------------------------------
    !> bin/bifilar_mpi and sweep_probe_mpi under mpirun (skipped, with a note, only when
    !! OpenMPI is not installed).
    subroutine test_mpi(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, mexe, probe, small, big, ck, line
        integer :: ex, np, k, n0, n1, nbad
        logical :: ok
        character(len=256) :: buf
        if (shell_count('(command -v mpirun > /dev/null && echo 1 || echo 0)', SCR) /= 1) then
            write (*, '(a)') 'note: OpenMPI is not installed (no mpirun): the MPI tests are '// &
                'skipped; make mpi installs it'
            return
        end if
        mexe = exe//'_mpi'
        probe = exe(1:index(exe, '/', back=.true.))//'sweep_probe_mpi'
        call t%check('mpi: '//mexe//' and '//probe//' are built (make test builds them '// &
                     'where mpif90 is)', all([exists(mexe), exists(probe)]))
        if (.not. all([exists(mexe), exists(probe)])) return
        d = SCR//'/sweep_mpi'
        call fresh_dir(d)
        mexe = abs_path(mexe)

        ex = run(MPIRUN//' -np 2 '//mexe//' --version', d)
        call t%check('mpi: --version names the MPI library', all([ex == 0, &
                     file_has(d//'/stdout', '(MPI: Open MPI')]))

        ! a small chart on 1, 2 and 3 ranks: the serial build's file, byte for byte
        small = d//'/small.nml'
        call write_text(small, BOX//"&chart x = 'l', x_min = 0.5, x_max = 8.0, nx = 12, "// &
                        "y = 'amplitude', y_min = 2.0, y_max = 90.0, ny = 9 /"//NL)
        ex = run(exe//' '//small//' --out '//d//'/serial', d)
        call t%check('mpi: serial chart (exit 0)', ex == 0)
        do np = 1, 3
            ex = run(MPIRUN//' -np '//itoa(np)//' '//mexe//' '//small//' --out '//d//'/np'// &
                     itoa(np), d)
            call t%check('mpi: -np '//itoa(np)//': exit 0, one stdout line, nothing on '// &
                         'stderr', all([ex == 0, count_lines(d//'/stdout') == 1, &
                         count_lines(d//'/stderr') == 0]))
            if (np > 1) call t%check('mpi: -np '//itoa(np)//': the summary says the ranks', &
                                     file_has(d//'/stdout', 'on '//itoa(np)//' ranks'))
            call t%check('mpi: -np '//itoa(np)//': chart = serial chart, byte for byte', &
                         same_file(d//'/np'//itoa(np)//'/small.chart.dat', d// &
                         '/serial/small.chart.dat'))
        end do

        ! a rig design (three sweeps, the edges' with its payload) on 1, 2 and 3 ranks
        call write_text(d//'/lb.nml', RIG//'&design l_min = 0.9, l_max = 1.2, nl = 7, '// &
                        'b_min = 0.18, b_max = 0.22, nb = 2, amplitude_max = 50, '// &
                        'n_amplitudes = 3 /'//NL)
        ex = run(exe//' '//d//'/lb.nml --out '//d//'/serial', d)
        call t%check('mpi design: serial design (exit 0, with band edges)', all([ex == 0, &
                     file_has(d//'/serial/lb.design', 'band_edges = ')]))
        call t%check('mpi design: it has edges to bisect', &
                     .not. file_has(d//'/serial/lb.design', 'band_edges = 0'))
        do np = 1, 3
            ex = run(MPIRUN//' -np '//itoa(np)//' '//mexe//' '//d//'/lb.nml --out '//d// &
                     '/dnp'//itoa(np), d)
            call t%check('mpi design: -np '//itoa(np)//': exit 0, one stdout line, nothing '// &
                         'on stderr', all([ex == 0, count_lines(d//'/stdout') == 1, &
                         count_lines(d//'/stderr') == 0]))
            call t%check('mpi design: -np '//itoa(np)//': design = serial design, byte for '// &
                         'byte', same_file(d//'/dnp'//itoa(np)//'/lb.design', d// &
                         '/serial/lb.design'))
        end do

        ! a rank killed mid-sweep: one line, no chart, the checkpoint; resumed on 2 ranks
        big = d//'/big.nml'
        call write_text(big, BOX//"&chart x = 'l', x_min = 0.5, x_max = 8.0, nx = 24, "// &
                        "y = 'amplitude', y_min = 2.0, y_max = 90.0, ny = 16 /"//NL)
        ex = run(exe//' '//big//' --out '//d//'/bigref', d)
        ck = d//'/big/big.chart.partial'
        ex = run('timeout 120 tests/tools/kill_run.sh '//ck//' rank1 '//MPIKILL//' -np 3 '//mexe// &
                 ' '//big//' --out '//d//'/big --checkpoint 0', d)
        call t%check('mpi kill: the run ends (mpirun exit 137 or 143, got '//itoa(ex)//')', &
                     ex == 137 .or. ex == 143)
        ok = all([count_lines(d//'/stderr') == 1, line_starts(d//'/stderr', 1, &
                 'bifilar: error (interrupted): '//big//': chart stopped by signal 15')])
        call t%check('mpi kill: one stderr line from rank 0 naming the deck', ok)
        if (.not. ok) call execute_command_line('sed "s/^/   stderr: /" '//d//'/stderr')
        call t%check('mpi kill: no chart, the checkpoint kept', all([.not. exists(d// &
                     '/big/big.chart.dat'), exists(ck), &
                     shell_count('ls -A '//d//'/big | wc -l', d) == 1]))
        ex = run(MPIRUN//' -np 2 '//mexe//' '//big//' --out '//d//'/big --resume', d)
        call t%check('mpi kill: resumed on 2 ranks (exit 0, points from the checkpoint)', &
                     all([ex == 0, resumed(d//'/stdout') > 0]))
        call t%check('mpi kill: resumed chart = uninterrupted serial chart, byte for byte', &
                     same_file(d//'/big/big.chart.dat', d//'/bigref/big.chart.dat'))

        ! ranks that see another deck (another folder: MPMD with -wdir), or none: the deck's
        ! text travels in the job message, so every rank takes rank 0's deck and needs no
        ! file of it
        call execute_command_line('mkdir -p '//d//'/w0 '//d//'/w1 && cp '//small//' '//d// &
            '/w0/ && sed "s/nx = 12/nx = 13/" '//small//' > '//d//'/w1/small.nml')
        ex = run(exe//' '//d//'/w0/small.nml --out '//d//'/w0ref', d)
        ex = run(mpmd(), d)
        call t%check('mpi other deck: exit 0 (got '//itoa(ex)//'): the ranks take rank 0''s '// &
                     'deck from the job message', ex == 0)
        call t%check('mpi other deck: the chart of rank 0''s deck, byte for byte (the deck''s '// &
                     'path aside)', same_chart())
        call execute_command_line('rm -rf '//d//'/w1/small.nml '//d//'/w0/out')
        ex = run(mpmd(), d)
        call t%check('mpi no deck on the other ranks: exit 0 (got '//itoa(ex)//')', ex == 0)
        call t%check('mpi no deck on the other ranks: the chart of rank 0''s deck', &
                     same_chart())

        ! the probe: dynamic sharing with threads in the ranks; failing points end the run
        call write_text(d//'/probe.fp', 'probe')
        ex = run(MPIENV//' OMP_NUM_THREADS=2 mpirun -q --oversubscribe --bind-to none -np 3 '// &
                 abs_path(probe)// &
                 ' ok 300 '//d//'/probe.fp', d)
        line = first_line(d//'/stdout')
        read (line(4:), *, iostat=k) n0, nbad, n0, n1
        call t%check('mpi probe: 3 ranks of 2 threads: 300 points, all right ('//line//')', &
                     ex == 0 .and. k == 0 .and. nbad == 0 .and. n0 + n1 == 300)
        call t%check('mpi probe: rank 0 and the others all computed points', &
                     k == 0 .and. n0 > 0 .and. n1 > 0)
        do k = 1, 2
            buf = merge('fail_worker', 'fail_rank0 ', k == 1)
            ex = run('timeout 120 '//MPIFAIL//' -np 3 '//abs_path(probe)//' '//trim(buf)// &
                     ' 200 '//d//'/probe.fp '//d//'/probe.partial', d)
            line = first_line(d//'/stdout')
            call t%check('mpi probe '//trim(buf)//': the run ends with the point''s error '// &
                         '(exit 3, '//line//')', all([ex == 3, index(line, 'error 3: probe '// &
                         'point ') == 1, index(line, trim(merge('on a worker', 'on rank 0  ', &
                         k == 1))) > 0]))
            call t%check('mpi probe '//trim(buf)//': its checkpoint removed', &
                         .not. exists(d//'/probe.partial'))
        end do

    contains

        !> The MPMD run's chart and the serial one's, the header line naming the deck's path
        !! (as given: relative to the run's folder) aside.
        logical function same_chart()
            call execute_command_line('grep -v "^# deck " '//d//'/w0/out/small.chart.dat > '// &
                d//'/w0/a.txt; grep -v "^# deck " '//d//'/w0ref/small.chart.dat > '//d//'/w0/b.txt')
            same_chart = same_file(d//'/w0/a.txt', d//'/w0/b.txt')
        end function same_chart

        !> rank 0 in w0, ranks 1 and 2 in w1, the deck small.nml as each sees it.
        function mpmd() result(c)
            character(len=:), allocatable :: c
            c = MPIFAIL//' -np 1 -wdir '//abs_path(d//'/w0')//' '//mexe//' small.nml --out out'// &
                ' : -np 2 -wdir '//abs_path(d//'/w1')//' '//mexe//' small.nml'
        end function mpmd

    end subroutine test_mpi

    ! ---------------------------------------------------------------------------------------
    !> Identify's Monte Carlo through bin/bifilar: killed (SIGKILL) after its first
    !! checkpoint and resumed, the uninterrupted .identify (cpu_seconds aside); the
    !! checkpoint removed with the commit.
    subroutine test_mc_resume(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, deck, ck
        integer :: ex, nres
        d = SCR//'/sweep_mc_kill'
        call fresh_dir(d)
        deck = d//'/per.nml'
        call write_text(deck, PERIODS//'monte_carlo = 2000 /'//NL)
        ck = d//'/out/per.identify_mc.partial'
        ex = run(exe//' '//deck//' --out '//d//'/ref', d)
        call t%check('mc kill: the uninterrupted run (exit 0)', all([ex == 0, &
                     exists(d//'/ref/per.identify')]))
        ex = run('OMP_NUM_THREADS=1 tests/tools/kill_run.sh '//ck//' KILL '//exe//' '//deck// &
                 ' --out '//d//'/out --checkpoint 0', d)
        call t%check('mc kill: killed after its first checkpoint (exit 137, got '// &
                     itoa(ex)//')', all([ex == 137, exists(ck), &
                     .not. exists(d//'/out/per.identify')]))
        ex = run(exe//' '//deck//' --out '//d//'/out --resume', d)
        nres = resumed(d//'/stdout')
        call t%check('mc kill: resumed (exit 0, '//itoa(nres)//' of 2000 samples from the '// &
                     'checkpoint)', ex == 0 .and. nres > 0 .and. nres < 2000)
        call t%check('mc kill: resumed .identify = uninterrupted .identify (cpu_seconds aside)', &
                     same_identify(d//'/out/per.identify', d//'/ref/per.identify'))
        call t%check('mc kill: the checkpoint is removed with the commit', .not. exists(ck))
    end subroutine test_mc_resume

    ! ---------------------------------------------------------------------------------------
    !> A Monte Carlo with samples that fail (periods drawn below the shortest period any
    !! positive I1 gives): the run ends with the first failed sample's error, the smallest
    !! k, found here by calling period_mc_sample for k = 1, 2, ...; no file, the checkpoint
    !! removed (the failure would repeat).
    subroutine test_mc_failure(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d
        type(deck_t) :: dk
        type(status_t) :: st
        type(period_fit_t) :: f
        type(input_u_t) :: u
        real(dp) :: i1
        integer :: ex, k, kfail
        d = SCR//'/sweep_mc_fail'
        call fresh_dir(d)
        call write_text(d//'/bad.nml', BADMC)
        call read_deck(d//'/bad.nml', dk, st)
        u = input_u_t(period=dk%measurement%u_period)
        call invert_periods(rig_of(dk), accuracy_of(dk), dk%measurement%periods(1:1), &
                            dk%measurement%amplitudes(1:1), u, f, st)
        kfail = 0
        do k = 1, dk%measurement%monte_carlo
            call period_mc_sample(rig_of(dk), accuracy_of(dk), dk%measurement%periods(1:1), &
                                  dk%measurement%amplitudes(1:1), u, f%i1, &
                                  dk%measurement%seed, k, i1, st)
            if (st%code /= STATUS_OK) then
                kfail = k
                exit
            end if
        end do
        call t%check('mc failure: some sample fails (sample '//itoa(kfail)//')', kfail > 1)
        ex = run(exe//' '//d//'/bad.nml --out '//d//'/out --checkpoint 0', d)
        call t%check('mc failure: exit 2, one line naming the first failed sample', &
                     all([ex == 2, count_lines(d//'/stderr') == 1, file_has(d//'/stderr', &
                     'bad.nml: Monte Carlo sample '//itoa(kfail)//': &measurement '// &
                     'periods(1) = ')]))
        call t%check('mc failure: no file, no checkpoint', &
                     empty_dir(d//'/out'))
    end subroutine test_mc_failure

    ! ---------------------------------------------------------------------------------------
    !> Identify's Monte Carlo under mpirun (skipped without OpenMPI): periods on 1, 2 and 3
    !! ranks and a record fit on 2 and 3 ranks give the serial .identify (cpu_seconds aside)
    !! and .fit.dat byte for byte, and so do 2 ranks of which rank 0 only hands out work
    !! (BIFILAR_RANK0_COMPUTES=no: every sample computed by rank 1 from the task it built
    !! from the deck and the payload, which carries rank 0's record: ranks beside another
    !! record file give the serial file too); the failed sample's error is the serial one.
    subroutine test_mpi_mc(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, mexe, how
        integer :: ex, np, k
        character(len=*), parameter :: HOWS(3) = [character(len=34) :: '-np 2', '-np 3', &
                                                   '-np 2 -x BIFILAR_RANK0_COMPUTES=no']
        if (shell_count('(command -v mpirun > /dev/null && echo 1 || echo 0)', SCR) /= 1) then
            write (*, '(a)') 'note: OpenMPI is not installed (no mpirun): the MPI tests of '// &
                'the Monte Carlo are skipped; make mpi installs it'
            return
        end if
        mexe = exe//'_mpi'
        call t%check('mpi mc: '//mexe//' is built', exists(mexe))
        if (.not. exists(mexe)) return
        mexe = abs_path(mexe)
        d = SCR//'/sweep_mpi_mc'
        call fresh_dir(d)

        ! periods: 1, 2, 3 ranks, and 2 of which rank 0 computes nothing
        call write_text(d//'/per.nml', PERIODS//'monte_carlo = 60, seed = 3 /'//NL)
        ex = run(exe//' '//d//'/per.nml --out '//d//'/serial', d)
        call t%check('mpi mc: serial periods Monte Carlo (exit 0)', all([ex == 0, &
                     file_has(d//'/serial/per.identify', 'u_I1_monte_carlo = ')]))
        do np = 1, 3
            ex = run(MPIRUN//' -np '//itoa(np)//' '//mexe//' '//d//'/per.nml --out '//d// &
                     '/np'//itoa(np), d)
            call t%check('mpi mc: -np '//itoa(np)//': exit 0, one stdout line, nothing on '// &
                         'stderr', all([ex == 0, count_lines(d//'/stdout') == 1, &
                         count_lines(d//'/stderr') == 0]))
            if (np > 1) call t%check('mpi mc: -np '//itoa(np)//': the summary says the ranks', &
                                     file_has(d//'/stdout', ' s on '//itoa(np)//' ranks)'))
            call t%check('mpi mc: -np '//itoa(np)//': .identify = serial .identify '// &
                         '(cpu_seconds aside)', same_identify(d//'/np'//itoa(np)// &
                         '/per.identify', d//'/serial/per.identify'))
        end do
        ex = run(MPIRUN//' -np 2 -x BIFILAR_RANK0_COMPUTES=no '//mexe//' '//d//'/per.nml '// &
                 '--out '//d//'/np2w', d)
        call t%check('mpi mc: -np 2, every sample on rank 1: exit 0, .identify = serial '// &
                     '.identify', all([ex == 0, count_lines(d//'/stderr') == 0, &
                     same_identify(d//'/np2w/per.identify', d//'/serial/per.identify')]))

        ! a record fit's Monte Carlo on 2 and 3 ranks, and on 2 of which rank 0 computes none
        call make_records(d)
        ex = run(exe//' '//d//'/w0/rec.nml --out '//d//'/rserial', d)
        call t%check('mpi mc: serial record Monte Carlo (exit 0)', all([ex == 0, &
                     file_has(d//'/rserial/rec.identify', 'u_I1_monte_carlo = ')]))
        do k = 1, 3
            how = trim(HOWS(k))
            ex = run(MPIRUN//' '//how//' '//mexe//' '//d//'/w0/rec.nml --out '//d//'/r'// &
                     itoa(k), d)
            call t%check('mpi mc: record, '//how//': exit 0, nothing on stderr, '// &
                         '.identify = serial (cpu_seconds aside), .fit.dat the same bytes', &
                         all([ex == 0, count_lines(d//'/stderr') == 0, file_has(d//'/stdout', &
                         'on '//how(5:5)//' ranks'), same_identify(d//'/r'//itoa(k)// &
                         '/rec.identify', d//'/rserial/rec.identify'), same_file(d//'/r'// &
                         itoa(k)//'/rec.fit.dat', d//'/rserial/rec.fit.dat')]))
        end do

        ! ranks 1, 2 see the same deck but another record: they never read it, the record
        ! travels from rank 0 with the Monte Carlo's payload: the serial file
        ex = run(MPIFAIL//' -np 1 -wdir '//abs_path(d//'/w0')//' '//mexe//' rec.nml --out out'// &
                 ' : -np 2 -wdir '//abs_path(d//'/w1')//' '//mexe//' rec.nml', d)
        call t%check('mpi mc: another record beside the other ranks: exit 0 (got '//itoa(ex)// &
                     '), nothing on stderr, .identify = serial (rank 0''s record)', &
                     all([ex == 0, count_lines(d//'/stderr') == 0, same_but_deck(d// &
                     '/w0/out/rec.identify', d//'/rserial/rec.identify')]))

        ! the failed sample: the serial error, on 2 ranks
        call write_text(d//'/bad.nml', BADMC)
        ex = run(exe//' '//d//'/bad.nml --out '//d//'/bad', d)
        call execute_command_line('cp '//d//'/stderr '//d//'/bad.serial')
        ex = run(MPIFAIL//' -np 2 '//mexe//' '//d//'/bad.nml --out '//d//'/bad', d)
        call t%check('mpi mc: a failed sample on 2 ranks: exit 2, the serial error line', &
                     all([ex == 2, same_file(d//'/stderr', d//'/bad.serial')]))
    end subroutine test_mpi_mc

    !> w0/rec.nml with its record w0/rec.dat (3 s of theta4 at 50 Hz of a damped rig with
    !! unequal cables, noise 2 mrad, seed 5), and in w1 the same deck with another record
    !! (noise seed 6).
    subroutine make_records(d)
        character(len=*), intent(in) :: d
        type(deck_t) :: truth
        type(status_t) :: st
        character(len=*), parameter :: RIG_REC = &
            '&suspension b = 0.4, b_prime = 0.4, l = 1.2, l_prime = 1.18, g = 9.80665 /'//NL// &
            '&start amplitude = 30 /'//NL//'&damping c_v = 2e-4, c_q = 5e-4 /'//NL
        integer :: k
        call execute_command_line('mkdir -p '//d//'/w0 '//d//'/w1')
        call write_text(d//'/truth.nml', "&scene analyses = 'simulate' /"//NL//RIG_REC// &
            '&body mass = 3.1, inertia = 0.0512, 0.063, 0.0304, r = 0.25, lambda = 0.64 /'//NL)
        call read_deck(d//'/truth.nml', truth, st)
        do k = 0, 1
            call make_record(rig_of(truth), start_of(truth), accuracy_of(truth), &
                             truth%scene%title, truth%path, 3.0_dp, 50.0_dp, 2.0e-3_dp, &
                             5 + k, 'angle', d//'/w'//itoa(k)//'/rec.dat', st)
            call write_text(d//'/w'//itoa(k)//'/rec.nml', "&scene analyses = 'identify' /"// &
                NL//RIG_REC//'&body mass = 3.1, inertia = 0.05, 0.063, 0.0304, r = 0.25, '// &
                'lambda = 0.64 /'//NL//"&measurement record = 'rec.dat', estimate = 'I1', "// &
                'u_mass = 0.001, u_b = 0.0005, monte_carlo = 8, seed = 11 /'//NL)
        end do
    end subroutine make_records

    ! ---------------------------------------------------------------------------------------
    ! helpers

    !> Two files are the same, byte for byte.
    logical function same_file(a, b)
        character(len=*), intent(in) :: a, b
        integer :: ex
        ex = -1
        if (all([exists(a), exists(b)])) call execute_command_line('cmp -s '//a//' '//b, &
                                                                   exitstat=ex)
        same_file = ex == 0
    end function same_file

    !> Two .identify files are the same, byte for byte, but for their cpu_seconds lines.
    logical function same_identify(a, b)
        character(len=*), intent(in) :: a, b
        integer :: ex
        ex = -1
        if (all([exists(a), exists(b)])) call execute_command_line('grep -v "^cpu_seconds = " '// &
            a//' > '//a//'.nocpu; grep -v "^cpu_seconds = " '//b//' > '//a//'.ref; cmp -s '// &
            a//'.nocpu '//a//'.ref', exitstat=ex)
        same_identify = ex == 0
    end function same_identify

    !> Two .identify files are the same but for their cpu_seconds and '# deck' lines (the
    !! deck named from another folder).
    logical function same_but_deck(a, b)
        character(len=*), intent(in) :: a, b
        integer :: ex
        ex = -1
        if (all([exists(a), exists(b)])) call execute_command_line('grep -v -e "^cpu_seconds'// &
            ' = " -e "^# deck " '//a//' > '//a//'.nodeck; grep -v -e "^cpu_seconds = " -e '// &
            '"^# deck " '//b//' > '//a//'.ref; cmp -s '//a//'.nodeck '//a//'.ref', exitstat=ex)
        same_but_deck = ex == 0
    end function same_but_deck

    !> Two files have the same lines apart from the '#' ones.
    logical function same_rows(a, b)
        character(len=*), intent(in) :: a, b
        integer :: ex
        ex = -1
        if (all([exists(a), exists(b)])) call execute_command_line('grep -v "^#" '//a// &
            ' > '//a//'.rows; grep -v "^#" '//b//' > '//a//'.ref; cmp -s '//a//'.rows '// &
            a//'.ref', exitstat=ex)
        same_rows = ex == 0
    end function same_rows

    !> The N of ', N resumed from the checkpoint' in a summary line (0 when absent).
    integer function resumed(path) result(n)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: s
        integer :: k, j, ios
        n = 0
        s = first_line(path)
        k = index(s, ' resumed from the checkpoint')
        if (k == 0) return
        j = index(s(1:k - 1), ' ', back=.true.)
        read (s(j + 1:k - 1), *, iostat=ios) n
        if (ios /= 0) n = -1
    end function resumed

end module test_sweep
