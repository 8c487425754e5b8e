!> Fuzz of what `--resume` reads and of stopping a run: the paths an audit took.
!!
!! - Checkpoints mutated pseudo-randomly (fixed seeds; module random) in 21 ways: a hex
!!   digit flipped, a quiet or signalling NaN, Inf or a value out of its range (with the
!!   record's checksum made anew, so that only the check of the values can refuse them, or
!!   not), cut short at any byte, bytes inserted, records duplicated, swapped, blank
!!   lines, the `done` count, the header's deck, executable, analysis, size or format
!!   changed, CR LF line ends, empty, too large, no comment line.  First in process, on
!!   the sweep engine with a probe task that checks its values exactly; then through the
!!   executable, on the checkpoints of a deck with every sweep (a chart, a design's three
!!   stages, identify's Monte Carlo).
!! - FIFOs, devices (links to /dev/zero, /dev/null, /dev/urandom), folders, links that lead
!!   nowhere and a sparse file of 200 MB where a checkpoint should be.
!! - SIGINT, SIGTERM and SIGHUP at every stage: as each sweep's first checkpoint appears,
!!   as a file is being written, at random moments, during a long simulation and during a
!!   record's fit; then the run resumed.  Under mpirun when there is one (skipped cleanly
!!   otherwise): the signal to mpirun, and to rank 0 itself.
!! - `--out` folders of random lengths and shapes around the system's limits.
!!
!! Every case through the executable checks: its exit status is in the documented set,
!! exactly one line on stdout or on stderr, no NaN, Inf or **** in any file, no temporary
!! file left, and, where the run finished, files equal to an uninterrupted run's
!! (cpu_seconds aside).
module test_fuzz_resume
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use testing, only: tester_t, write_text, exists, file_has, count_lines, line_starts, &
        message_lines, &
                       first_line, run, shell_count, scratch_dir, fresh_dir, abs_path, no_nan
    use text, only: itoa
    use status, only: status_t, STATUS_OK
    use random, only: rng_t, rng_stream, rng_uniform
    use crc64, only: crc64_of, hex16
    use sweep_engine, only: sweep_resume_points
    use checkpoint, only: checkpoint_write
    use probe_task, only: probe_task_t
    implicit none
    private

    public :: run_fuzz_resume_tests

    character(len=*), parameter :: SCR = 'build/test_fuzz_resume'
    character, parameter :: NL = new_line('a')
    character(len=*), parameter :: HEX = '0123456789ABCDEF'

    !> The mutations of a checkpoint (see `mutate`), and what a resume must then do: take
    !! all but one point (EXP_ONE), take none and say why (EXP_NOTE), or take some (EXP_ANY).
    integer, parameter :: NKINDS = 21
    character(len=12), parameter :: KIND_NAMES(NKINDS) = [character(len=12) :: 'flip', &
        'nan_sealed', 'nan', 'inf_sealed', 'range_sealed', 'truncate', 'garbage', 'dup', &
        'swap', 'done_count', 'foreign', 'executable', 'analysis', 'points', 'format', &
        'crlf', 'empty', 'too_large', 'extra_field', 'blank_line', 'no_comment']
    integer, parameter :: EXP_ONE = 1, EXP_NOTE = 2, EXP_ANY = 3

    !> A deck with every sweep, cheap: a chart of 4 x 3 points, a design of 8 candidates at
    !! 2 amplitudes with one band edge, identify's Monte Carlo of 200 samples from periods,
    !! a Floquet analysis and a simulation (the laboratory rig of input/identify_periods.nml).
    character(len=*), parameter :: ALL_DECK = &
        "&scene title = 'fuzz resume: every sweep', "// &
        "analyses = 'chart design identify simulate floquet' /"//NL// &
        '&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.20, g = 9.80665 /'//NL// &
        '&body mass = 3.10, inertia = 0.045, 0.0630, 0.0304, r = 0.25, '// &
        'lambda = 0.6435011087932844, sway_depth = 0.30 /'//NL// &
        "&start mode = 'raised', amplitude = 30.0 /"//NL// &
        '&integration tau_end = 100.0, dtau_out = 0.05 /'//NL// &
        '&floquet amplitude = 30.0, rtol = 1e-6 /'//NL// &
        "&chart x = 'l', x_min = 1.0, x_max = 8.0, nx = 4, y = 'amplitude', y_min = 5.0, "// &
        'y_max = 60.0, ny = 3 /'//NL// &
        '&design l_min = 0.3, l_max = 4.0, nl = 8, amplitude_max = 60, n_amplitudes = 2 /'//NL// &
        '&measurement periods = 1.41564, 1.44107, 1.52913, amplitudes = 10.0, 30.0, 60.0,'// &
        NL//'      u_mass = 0.001, u_l = 0.001, u_l_prime = 0.001, u_b = 0.0005, '// &
        'u_b_prime = 0.0005,'//NL//'      u_period = 1e-4, u_amplitude = 0.5, '// &
        'monte_carlo = 200 /'//NL
    !> ALL_DECK with its sweeps alone (what a resume recomputes is then only what a
    !! mutation damaged, and identify's fit).
    character(len=*), parameter :: SWEEP_DECK = "&scene analyses = 'chart design identify' /"// &
        NL//ALL_DECK(index(ALL_DECK, '&suspension'):)
    !> The sweeps' checkpoints of ALL_DECK and SWEEP_DECK (NAME.X.partial).
    integer, parameter :: NSWEEPS = 5
    character(len=16), parameter :: SWEEPS(NSWEEPS) = [character(len=16) :: 'chart', &
        'design', 'design_edges', 'design_precision', 'identify_mc']
    !> A long simulation (the paper's cylinder for 20 000 tau: about a second).
    character(len=*), parameter :: SIM_DECK = &
        "&scene title = 'fuzz resume: a long simulation', analyses = 'simulate' /"//NL// &
        '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 1.8, g = 1.0 /'//NL// &
        '&body mass = 1.0, inertia = 0.125, 0.1458333333333333, 0.1458333333333333,'//NL// &
        '      r = 0.7071067811865476, lambda = 0.7853981633974483, sway_depth = 1.0 /'//NL// &
        "&start mode = 'raised', amplitude = 45.0 /"//NL// &
        '&integration tau_end = 20000.0, dtau_out = 0.2, rtol = 1e-10, atol = 1e-12 /'//NL
    !> A chart for mpirun: 48 x 32 points (the box of input/box_chart.nml), about 2 s on 2
    !! ranks: mpirun passes an interrupt on only after odls_base_sigkill_timeout (1 s).  Its
    !! monodromies by the variational system (sensitivities = 'differences'): the forward
    !! sensitivities finish it in well under that second.
    character(len=*), parameter :: MPI_DECK = &
        "&scene title = 'fuzz resume: chart under mpirun', analyses = 'chart' /"//NL// &
        '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 2.0, g = 1.0 /'//NL// &
        '&body mass = 1.0, inertia = 0.08854166666666667, 1.416666666666667, '// &
        '1.338541666666667,'//NL// &
        '      r = 2.06155281280883, lambda = 1.325817663668033, sway_depth = 4 /'//NL// &
        '&floquet amplitude = 45.0, segments = 1, rtol = 1e-6 /'//NL// &
        "&chart x = 'l', x_min = 0.5, x_max = 8.0, nx = 48, y = 'amplitude', y_min = 2.0, "// &
        'y_max = 90.0, ny = 32 /'//NL// &
        "&integration sensitivities = 'differences' /"//NL
    !> A short simulation, for --out.
    character(len=*), parameter :: SHORT_DECK = &
        "&scene title = 'fuzz resume: --out', analyses = 'simulate' /"//NL// &
        '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 1.8, g = 1.0 /'//NL// &
        '&body mass = 1.0, inertia = 0.125, 0.1458333333333333, 0.1458333333333333,'//NL// &
        '      r = 0.7071067811865476, lambda = 0.7853981633974483 /'//NL// &
        '&integration tau_end = 0.5, dtau_out = 0.1 /'//NL
    !> mpirun as the tests run it (as root too, more ranks than cores, no notes of its own).
    character(len=*), parameter :: MPIRUN = 'env OMPI_ALLOW_RUN_AS_ROOT=1 '// &
        'OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 mpirun -q --oversubscribe'

contains

    subroutine run_fuzz_resume_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCR)
        if (t%want('fuzz_resume: checkpoints mutated in process, resumed by the engine')) &
            call test_probe(t)
        if (t%want('fuzz_resume: chart, design and Monte Carlo checkpoints mutated, resumed')) &
            call test_mutated(t, exe)
        if (t%want('fuzz_resume: FIFOs, devices, folders and links as checkpoints')) &
            call test_devices(t, exe)
        if (t%want('fuzz_resume: signals at every stage, then resumed')) &
            call test_signals(t, exe)
        if (t%want('fuzz_resume: signals under mpirun')) call test_mpi_signals(t, exe)
        if (t%want('fuzz_resume: --out names around the system''s limits')) &
            call test_out(t, exe)
    end subroutine run_fuzz_resume_tests

    ! ---------------------------------------------------------------------------------------
    !> The sweep engine in process (sweep_resume_points: the checkpoint's reader, then each
    !! value checked as if computed), with a probe task that accepts only its own values
    !! (strict): a whole checkpoint of 40 points mutated 21 x 16 ways.  Every point taken
    !! must be exact; one damaged record alone is refused, the rest taken; a foreign or
    !! broken header gives no point and says why.
    subroutine test_probe(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: N = 40, ROUNDS = 16
        integer(int64), parameter :: DECK_CRC = 2201_int64, EXE_CRC = -77_int64
        type(probe_task_t) :: task
        type(status_t) :: st
        real(dp) :: truth(4, N)
        real(dp), allocatable :: v(:, :)
        logical :: done(N)
        character(len=:), allocatable :: ck, full, mutated, note, why
        type(rng_t) :: g
        integer :: k, i, r, expect, nfail, ntaken, nrej, nnone, ndone, nbad
        logical :: ok
        ck = SCR//'/probe.probe.partial'
        task%n = N
        task%strict = .true.
        do i = 1, N
            truth(:, i) = [real(i, dp), sqrt(real(i, dp)), 0.0_dp, 1.0_dp]
        end do
        call checkpoint_write(ck, 'probe', DECK_CRC, EXE_CRC, truth, [(.true., i=1, N)], st)
        call t%check('probe: a whole checkpoint of 40 points', all([st%code == STATUS_OK, &
                     exists(ck)]))
        if (st%code /= STATUS_OK) return
        full = read_file(ck)
        g = rng_stream(2201, 1)
        nfail = 0
        ntaken = 0
        nrej = 0
        nnone = 0
        allocate (v(4, N))
        do r = 1, ROUNDS
            do k = 1, NKINDS
                call mutate(full, g, k, 'probe', mutated, expect, note)
                call write_file(ck, mutated)
                v = 0.0_dp
                done = .false.
                call sweep_resume_points(task, ck, 'probe', DECK_CRC, EXE_CRC, v, done, &
                                         ndone, nbad, why)
                ok = ndone == count(done) .and. ndone >= 0 .and. nbad >= 0
                do i = 1, N
                    if (done(i)) then
                        if (any(v(:, i) /= truth(:, i))) ok = .false.
                    else
                        if (any(v(:, i) /= 0.0_dp)) ok = .false.
                    end if
                end do
                select case (expect)
                case (EXP_ONE)
                    if (ok) ok = ndone == N - 1 .and. nbad == 1 .and. len(why) == 0
                case (EXP_NOTE)
                    if (ok) ok = ndone == 0 .and. index(why, note) > 0
                end select
                if (.not. ok) then
                    nfail = nfail + 1
                    if (nfail <= 5) write (*, '(a)') '   probe: '//trim(KIND_NAMES(k))// &
                        ' round '//itoa(r)//': taken '//itoa(ndone)//', refused '// &
                        itoa(nbad)//', note "'//why//'"'
                end if
                ntaken = ntaken + ndone
                nrej = nrej + nbad
                if (ndone == 0) nnone = nnone + 1
            end do
        end do
        write (*, '(a)') '   fuzz_resume: '//itoa(ROUNDS*NKINDS)//' probe checkpoints '// &
            'mutated in '//itoa(NKINDS)//' ways: '//itoa(ntaken)//' points taken, '// &
            itoa(nrej)//' damaged or refused, '//itoa(nnone)//' checkpoints not used at all'
        call t%check('probe: '//itoa(ROUNDS*NKINDS)//' mutated checkpoints read: every point '// &
                     'taken exact, one damaged record alone refused, a foreign or broken '// &
                     'header refused with its reason ('//itoa(nfail)//' failed)', nfail == 0)
        call t%check('probe: the fuzz both took points and refused some', ntaken > 0 .and. &
                     nrej > 0 .and. nnone > 0)
    end subroutine test_probe

    ! ---------------------------------------------------------------------------------------
    !> Through the executable: SWEEP_DECK's five checkpoints, whole (made by a run whose commit
    !! fails: NAME.chart.dat is a folder), mutated one at a time and resumed.  Every resume:
    !! exit 0, one stdout line saying what was taken or why not, nothing on stderr, files
    !! equal to the uninterrupted run's, no checkpoint or temporary file left, no NaN.
    subroutine test_mutated(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: NCASES = 2*NKINDS
        character(len=:), allocatable :: d, deck, seed, c, ck, mutated, note, full
        type(rng_t) :: g
        integer :: k, ex, kind, w, expect, nfail
        logical :: ok, have_all
        d = SCR//'/mutated'
        call fresh_dir(d)
        deck = d//'/all.nml'
        call write_text(deck, SWEEP_DECK)
        call make_reference(exe, deck, d//'/ref', d, ok)
        call t%check('mutated: the uninterrupted run (exit 0)', ok)
        seed = d//'/seed'
        call make_full_checkpoints(exe, deck, seed, d, have_all)
        call t%check('mutated: a run whose commit fails keeps all five checkpoints, whole', &
                     have_all)
        if (.not. (ok .and. have_all)) return
        c = d//'/c'
        g = rng_stream(2202, 1)
        nfail = 0
        do k = 1, NCASES
            kind = mod(k - 1, NKINDS) + 1
            w = pick(g, NSWEEPS)
            call execute_command_line('rm -rf '//c//' && mkdir -p '//c//' && cp '//seed// &
                                      '/*.partial '//c//'/')
            ck = c//'/all.'//trim(SWEEPS(w))//'.partial'
            full = read_file(ck)
            call mutate(full, g, kind, trim(SWEEPS(w)), mutated, expect, note)
            call write_file(ck, mutated)
            ex = run('OMP_NUM_THREADS=1 '//exe//' '//deck//' --out '//c//' --resume', d)
            ok = all([ex == 0, count_lines(d//'/stdout') == 1, message_lines(d//'/stderr') == 0, &
                      same_outputs(c, d//'/ref', d), clean(c, d), no_nan(c)])
            select case (expect)
            case (EXP_ONE)
                if (ok) ok = file_has(d//'/stdout', ', 1 of its points damaged or out of '// &
                                      'range: computed again')
            case (EXP_NOTE)
                if (ok) ok = file_has(d//'/stdout', note)
            end select
            if (.not. ok) then
                nfail = nfail + 1
                if (nfail <= 5) then
                    write (*, '(a)') '   mutated: '//trim(KIND_NAMES(kind))//' of '// &
                        trim(SWEEPS(w))//': exit '//itoa(ex)//': '//first_line(d//'/stdout')// &
                        first_line(d//'/stderr')
                    call execute_command_line('mkdir -p '//d//'/failed'//itoa(k)//' && cp -r '// &
                        c//' '//d//'/failed'//itoa(k)//'/ && cp '//ck//' '//d//'/failed'// &
                        itoa(k)//'/')
                end if
            end if
        end do
        write (*, '(a)') '   fuzz_resume: '//itoa(NCASES)//' runs resumed from checkpoints '// &
            'of a '// &
            'chart, a design''s three stages and a Monte Carlo, mutated in '//itoa(NKINDS)// &
            ' ways'
        call t%check('mutated: '//itoa(NCASES)//' resumes from mutated checkpoints: exit 0, '// &
                     'one line saying what was taken or why not, the uninterrupted files, '// &
                     'nothing left, no NaN ('//itoa(nfail)//' failed)', nfail == 0)
    end subroutine test_mutated

    ! ---------------------------------------------------------------------------------------
    !> What is not a checkpoint at NAME.X.partial: a FIFO (its open would block), links to
    !! /dev/zero (reads for ever), /dev/null and /dev/urandom, a folder, a link that leads
    !! nowhere, a sparse file of 200 MB.  Each is refused at once (under timeout 20): exit 0,
    !! the summary says why, the uninterrupted files.
    subroutine test_devices(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: NDEV = 7
        character(len=24), parameter :: DEVS(NDEV) = [character(len=24) :: 'fifo', &
            'link /dev/zero', 'link /dev/null', 'link /dev/urandom', 'folder', &
            'link nowhere', 'sparse 200 MB']
        character(len=40), parameter :: SAYS(NDEV) = [character(len=40) :: &
            'not a regular file (a FIFO)', 'not a regular file (a character device)', &
            'not a regular file (a character device)', &
            'not a regular file (a character device)', 'not a regular file (a folder)', &
            '', 'larger than one of this sweep can be']
        character(len=:), allocatable :: d, deck, seed, c, ck, make
        type(rng_t) :: g
        integer :: k, r, w, ex, nfail
        logical :: ok, have_all
        d = SCR//'/devices'
        call fresh_dir(d)
        deck = d//'/all.nml'
        call write_text(deck, SWEEP_DECK)
        call make_reference(exe, deck, d//'/ref', d, ok)
        seed = d//'/seed'
        call make_full_checkpoints(exe, deck, seed, d, have_all)
        if (.not. (ok .and. have_all)) then
            call t%check('devices: the reference run and its checkpoints', .false.)
            return
        end if
        c = d//'/c'
        g = rng_stream(2203, 1)
        nfail = 0
        do r = 1, 1
            do k = 1, NDEV
                w = pick(g, NSWEEPS)
                call execute_command_line('rm -rf '//c//' && mkdir -p '//c//' && cp '//seed// &
                                          '/*.partial '//c//'/')
                ck = c//'/all.'//trim(SWEEPS(w))//'.partial'
                make = ''
                select case (k)
                case (1)
                    make = 'mkfifo '//ck
                case (2, 3, 4)
                    make = 'ln -s '//DEVS(k)(6:)//' '//ck
                case (5)
                    make = 'mkdir '//ck
                case (6)
                    make = 'ln -s '//abs_path(c)//'/no/such/file '//ck
                case default
                    make = 'truncate -s 200M '//ck
                end select
                call execute_command_line('rm -f '//ck//' && '//make)
                ex = run('OMP_NUM_THREADS=1 timeout 20 '//exe//' '//deck//' --out '//c// &
                         ' --resume', d)
                ok = all([ex == 0, count_lines(d//'/stdout') == 1, &
                          message_lines(d//'/stderr') == 0, same_outputs(c, d//'/ref', d), &
                          no_nan(c)])
                if (ok .and. len_trim(SAYS(k)) > 0) ok = file_has(d//'/stdout', trim(SAYS(k)))
                ! (a folder at the checkpoint's name stays: it is not a file to remove)
                if (ok .and. k /= 5) ok = clean(c, d)
                if (.not. ok) then
                    nfail = nfail + 1
                    write (*, '(a)') '   devices: '//trim(DEVS(k))//' as '//trim(SWEEPS(w))// &
                        ': exit '//itoa(ex)//': '//first_line(d//'/stdout')// &
                        first_line(d//'/stderr')
                end if
            end do
        end do
        write (*, '(a)') '   fuzz_resume: '//itoa(NDEV)//' runs with FIFOs, devices, '// &
            'folders, dangling links and a sparse file as checkpoints'
        call t%check('devices: '//itoa(NDEV)//' checkpoints that are no files refused at '// &
                     'once with the reason, the uninterrupted files ('//itoa(nfail)// &
                     ' failed)', nfail == 0)
    end subroutine test_devices

    ! ---------------------------------------------------------------------------------------
    !> SIGINT, SIGTERM and SIGHUP at every stage of ALL_DECK (as each sweep's first
    !! checkpoint appears, as a staged file appears, at random moments from 20 ms after the
    !! start), then the run resumed; during a long simulation and during a record's fit.
    !! (In its first milliseconds, before bifilar installs its handlers, a signal ends the
    !! process by its default action with no line: the random moments start after that, as
    !! those of the simulation and the fit do.)  A run that took the signal: exit 128 + n,
    !! one stderr line naming the deck, the signal and what is kept (which exists), nothing
    !! but checkpoints left; resumed: exit 0 and the uninterrupted files.  A run that ended
    !! first: exit 0 and the uninterrupted files.
    subroutine test_signals(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: NTRIG = 11, NALL = 12
        character(len=32), parameter :: TRIGGERS(NTRIG) = [character(len=32) :: &
            'all.chart.partial', 'all.design.partial', 'all.design_edges.partial', &
            'all.design_precision.partial', 'all.identify_mc.partial', 'all.chart.dat.tmp.*', &
            'all.identify.tmp.*', 'all.dat.tmp.*', '', '', '']
        character(len=7), parameter :: SIGNAMES(3) = ['SIGINT ', 'SIGTERM', 'SIGHUP ']
        character(len=4), parameter :: SIGS(3) = ['INT ', 'TERM', 'HUP ']
        integer, parameter :: SIGNUMS(3) = [2, 15, 1]
        character(len=:), allocatable :: d, deck, o, when
        type(rng_t) :: g
        integer :: k, s, ex, nfail, nstopped, nfinished, j
        real(dp) :: secs, tref
        integer(int64) :: c0, c1, rate
        logical :: ok, refd
        d = SCR//'/signals'
        call fresh_dir(d)
        deck = d//'/all.nml'
        call write_text(deck, ALL_DECK)
        call system_clock(c0, rate)
        call make_reference(exe, deck, d//'/ref', d, ok)
        call system_clock(c1)
        tref = real(c1 - c0, dp)/real(rate, dp)     ! (only to spread the random moments)
        call t%check('signals: the uninterrupted run (exit 0)', ok)
        if (.not. ok) return
        o = d//'/o'
        g = rng_stream(2204, 1)
        nfail = 0
        nstopped = 0
        nfinished = 0
        do k = 1, NALL
            s = mod(k - 1, 3) + 1
            j = mod(k - 1, NTRIG) + 1
            if (len_trim(TRIGGERS(j)) > 0) then
                when = 'file:'//o//'/'//trim(TRIGGERS(j))
            else
                secs = 0.02_dp + 1.2_dp*tref*rng_uniform(g)
                when = fixed3(secs)
            end if
            call execute_command_line('rm -rf '//o//' && mkdir -p '//o)
            ex = run('tests/tools/signal_run.sh '//trim(SIGS(s))//' '''//when//''' '//exe// &
                     ' '//deck//' --out '//o//' --checkpoint 0', d)
            if (ex == 0) then
                nfinished = nfinished + 1
                ok = finished_ok(o, d//'/ref')
            else
                nstopped = nstopped + 1
                ok = stopped_ok(d, o, deck, ex, SIGNUMS(s), trim(SIGNAMES(s)), .true.)
                ex = run(exe//' '//deck//' --out '//o//' --resume', d)
                if (ok) ok = ex == 0
                if (ok) ok = finished_ok(o, d//'/ref')
            end if
            if (.not. ok) then
                nfail = nfail + 1
                write (*, '(a)') '   signals: SIG'//trim(SIGS(s))//' at '//when//': exit '// &
                    itoa(ex)//': '//first_line(d//'/stdout')//first_line(d//'/stderr')
            end if
        end do

        ! a long simulation, and a record's fit (input/identify_record.nml): each stopped at
        ! a random moment; nothing is kept
        call write_text(d//'/sim.nml', SIM_DECK)
        call execute_command_line('cp input/identify_record.nml '// &
                                  'input/identify_record_swing.dat '//d//'/')
        call execute_command_line('sed -i "s#record = ''[^'']*''#record = '// &
            '''identify_record_swing.dat''#" '//d//'/identify_record.nml')
        refd = .false.
        do k = 1, 6
            s = mod(k - 1, 3) + 1
            if (k <= 3) then
                deck = d//'/sim.nml'
                secs = 0.02_dp + 0.3_dp*rng_uniform(g)
            else
                deck = d//'/identify_record.nml'
                secs = 0.05_dp + 0.3_dp*rng_uniform(g)
            end if
            call execute_command_line('rm -rf '//o//' && mkdir -p '//o)
            ex = run('tests/tools/signal_run.sh '//trim(SIGS(s))//' '//fixed3(secs)//' '// &
                     exe//' '//deck//' --out '//o, d)
            if (ex == 0) then
                ! (it ended first: compare it with a run of its own)
                nfinished = nfinished + 1
                call make_reference(exe, deck, d//'/ref'//itoa(k), d, refd)
                ok = refd
                if (ok) ok = finished_ok(o, d//'/ref'//itoa(k))
            else
                nstopped = nstopped + 1
                ok = stopped_ok(d, o, deck, ex, SIGNUMS(s), trim(SIGNAMES(s)), .false.)
                if (ok) ok = shell_count('ls -A '//o//' | wc -l', d) == 0
            end if
            if (.not. ok) then
                nfail = nfail + 1
                write (*, '(a)') '   signals: SIG'//trim(SIGS(s))//' after '//fixed3(secs)// &
                    ' s of '//deck//': exit '//itoa(ex)//': '//first_line(d//'/stdout')// &
                    first_line(d//'/stderr')
            end if
        end do
        write (*, '(a)') '   fuzz_resume: '//itoa(NALL + 6)//' runs signalled: '// &
            itoa(nstopped)//' stopped (then resumed where a sweep kept its points), '// &
            itoa(nfinished)//' ended first'
        call t%check('signals: '//itoa(NALL + 6)//' runs signalled at every stage: exit '// &
                     '128 + n with one line naming the signal, nothing but checkpoints left, '// &
                     'resumed to the uninterrupted files ('//itoa(nfail)//' failed)', nfail == 0)
        call t%check('signals: most runs were stopped', nstopped >= 9)

    contains

        !> A run stopped by signal n: one stderr line naming the deck and the signal, nothing
        !! on stdout, no temporary file, only checkpoints (sweeps), the one named kept there.
        logical function stopped_ok(d, o, deck, ex, n, name, sweeps) result(ok)
            character(len=*), intent(in) :: d, o, deck, name
            integer, intent(in) :: ex, n
            logical, intent(in) :: sweeps
            character(len=:), allocatable :: l, kept
            integer :: p, q
            ok = all([ex == 128 + n, message_lines(d//'/stderr') == 1, &
                      count_lines(d//'/stdout') == 0, &
                      line_starts(d//'/stderr', 1, 'bifilar: error (interrupted): '//deck//': '), &
                      file_has(d//'/stderr', 'stopped by signal '//itoa(n)//' ('//name//')'), &
                      clean_but_checkpoints(o, d), no_nan(o)])
            l = first_line(d//'/stderr')
            p = index(l, 'kept in ')
            q = index(l, ': run again with --resume')
            if (ok .and. p > 0 .and. q > p) then
                kept = l(p + 8:q - 1)
                ok = sweeps
                if (ok) ok = exists(kept)
            end if
        end function stopped_ok

    end subroutine test_signals

    ! ---------------------------------------------------------------------------------------
    !> Under mpirun (2 ranks; skipped without OpenMPI): SIGINT and SIGHUP to mpirun as the
    !! chart's first checkpoint appears: mpirun passes SIGTERM on to the ranks (after
    !! odls_base_sigkill_timeout) and ends with its own status 1 (OpenMPI's;
    !! doc/parallel.md); rank 0's one line names signal 15 and the checkpoint, which alone
    !! is left.  SIGTERM to rank 0 itself: mpirun ends with rank 0's 143.  (Suite sweep mpi
    !! resumes such a chart to the serial file.)
    subroutine test_mpi_signals(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: HOW(3) = ['INT         ', 'HUP         ', &
                                                 'TERM rank0: ']
        character(len=:), allocatable :: d, deck, mexe, o, sig, to
        integer :: k, ex, nfail, nstopped, p
        logical :: ok
        d = SCR//'/mpi'
        call fresh_dir(d)
        mexe = exe//'_mpi'
        k = shell_count('(command -v mpirun > /dev/null && echo 1 || echo 0)', d)
        ok = exists(mexe)
        if (k /= 1 .or. .not. ok) then
            write (*, '(a)') '   fuzz_resume: no mpirun or no '//mexe//': the MPI signals '// &
                'are skipped'
            return
        end if
        mexe = abs_path(mexe)
        deck = d//'/mchart.nml'
        call write_text(deck, MPI_DECK)
        o = d//'/o'
        nfail = 0
        nstopped = 0
        do k = 1, size(HOW)
            call execute_command_line('rm -rf '//o//' && mkdir -p '//o)
            p = index(HOW(k), ' ')
            sig = HOW(k)(1:p - 1)
            to = trim(HOW(k)(p + 1:))
            ex = run('tests/tools/signal_run.sh '//sig//' '//to//'file:'//o// &
                     '/mchart.chart.partial '//MPIRUN//' -np 2 '//mexe//' '//deck// &
                     ' --out '//o//' --checkpoint 0', d)
            if (count_lines(d//'/stdout') == 1) then
                ! (the chart ended before mpirun passed the signal on: it is whole)
                ok = all([ex == 0 .or. ex == 1, message_lines(d//'/stderr') == 0, &
                          exists(o//'/mchart.chart.dat'), clean(o, d), no_nan(o)])
            else
                nstopped = nstopped + 1
                ok = all([ex == merge(143, 1, len(to) > 0), message_lines(d//'/stderr') == 1, &
                          count_lines(d//'/stdout') == 0, &
                          line_starts(d//'/stderr', 1, 'bifilar: error (interrupted): '// &
                          deck//': chart stopped by signal 15 (SIGTERM)'), &
                          file_has(d//'/stderr', 'kept in '//o//'/mchart.chart.partial'), &
                          clean_but_checkpoints(o, d), exists(o//'/mchart.chart.partial'), &
                          no_nan(o)])
            end if
            if (.not. ok) then
                nfail = nfail + 1
                write (*, '(a)') '   mpi: SIG'//sig//' to '//merge('rank 0', 'mpirun', &
                    len(to) > 0)//': exit '//itoa(ex)//': '//first_line(d//'/stdout')// &
                    first_line(d//'/stderr')
            end if
        end do
        write (*, '(a)') '   fuzz_resume: '//itoa(size(HOW))//' runs under mpirun signalled, '// &
            itoa(nstopped)//' stopped'
        call t%check('mpi: SIGINT, SIGHUP to mpirun and SIGTERM to rank 0: mpirun''s status '// &
                     '(1, or rank 0''s 143), rank 0''s one line naming SIGTERM and the '// &
                     'checkpoint, only the checkpoint left ('//itoa(nfail)//' failed)', &
                     nfail == 0)
    end subroutine test_mpi_signals

    ! ---------------------------------------------------------------------------------------
    !> --out folders of random shapes: 1 to 22 parts of 1 ... 300 characters (around 255),
    !! paths around 4096 characters, '//', '.', '..', trailing '/', blanks and non-ASCII
    !! letters, a file in the way; and decks with long names.  Each is exit 0 with the
    !! files where --out says, or exit 5 with one line and nothing created.
    subroutine test_out(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer, parameter :: NCASES = 48
        integer, parameter :: LENS(8) = [1, 12, 60, 200, 240, 255, 256, 300]
        character(len=:), allocatable :: d, base, out, part, deck, name, before
        type(rng_t) :: g
        integer :: k, j, nparts, ex, nfail, n0, n5, lp, kind
        logical :: ok
        d = SCR//'/out'
        call fresh_dir(d)
        base = abs_path(d)//'/o'
        call execute_command_line('mkdir -p '//base//' && echo x > '//base//'/a_file')
        g = rng_stream(2205, 1)
        nfail = 0
        n0 = 0
        n5 = 0
        before = ''
        do k = 1, NCASES
            name = 'deck'
            if (mod(k, 8) == 0) then
                lp = 180 + pick(g, 60)              ! a deck name near the limit
                name = repeat('n', lp)
            end if
            deck = d//'/'//name//'.nml'
            call write_text(deck, SHORT_DECK)
            out = base
            kind = pick(g, 4)
            nparts = pick(g, 22)
            if (kind == 1) nparts = min(nparts, 3)
            do j = 1, nparts
                lp = LENS(pick(g, 8))
                if (kind /= 4) lp = min(lp, 200)
                part = repeat(achar(iachar('a') + pick(g, 26) - 1), lp)
                select case (pick(g, 12))
                case (1)
                    part = '.'
                case (2)
                    part = 'a_file'                 ! a file in the way (at the top only)
                case (3)
                    part = part(1:max(1, len(part) - 2))//'é'
                case (4)
                    part = 'sp ace'
                end select
                out = out//'/'//part
                if (pick(g, 10) == 1) out = out//'/'
            end do
            if (pick(g, 6) == 1) out = out//'/'
            before = listing(base, d)
            ex = run(exe//' '''//deck//''' --out '''//out//'''', d)
            if (ex == 0) then
                n0 = n0 + 1
                ok = all([count_lines(d//'/stdout') == 1, message_lines(d//'/stderr') == 0, &
                          exists(out//'/'//name//'.dat'), exists(out//'/'//name//'.summary')])
            else
                n5 = n5 + 1
                ok = all([ex == 5, count_lines(d//'/stdout') == 0, &
                          message_lines(d//'/stderr') == 1, &
                          line_starts(d//'/stderr', 1, 'bifilar: error (cannot write output): ')])
                ! (nothing created; a deck's name too long for the folder: its folder may be
                ! made, since other decks could use it, but holds no file)
                if (ok .and. len(name) <= 100) ok = listing(base, d) == before
                if (ok) ok = shell_count('find '//base//' -type f | wc -l', d) == 1
            end if
            if (.not. ok) then
                nfail = nfail + 1
                if (nfail <= 5) write (*, '(a)') '   out: --out of '//itoa(len(out))// &
                    ' characters, deck name of '//itoa(len(name))//': exit '//itoa(ex)// &
                    ': '//first_line(d//'/stderr')
            end if
            call execute_command_line('rm -rf '//base//'/[!a]* '//base//'/a[!_]* '//base// &
                                      '/a '//base//'/.[!.]*')
        end do
        write (*, '(a)') '   fuzz_resume: '//itoa(NCASES)//' --out names: '//itoa(n0)// &
            ' written, '//itoa(n5)//' refused'
        call t%check('out: '//itoa(NCASES)//' --out names: written where they say, or exit '// &
                     '5 with one line and nothing created ('//itoa(nfail)//' failed)', &
                     nfail == 0)
        call t%check('out: both kinds met', n0 > 0 .and. n5 > 0)
    end subroutine test_out

    ! =======================================================================================
    ! mutations

    !> Checkpoint text s mutated in way `kind` (KIND_NAMES) for the sweep `analysis`, with
    !! draws from g: out, and what a resume must do (expect) with, for EXP_NOTE, a word of
    !! its note.
    subroutine mutate(s, g, kind, analysis, out, expect, note)
        character(len=*), intent(in) :: s           !! a whole checkpoint of format 2
        type(rng_t), intent(inout) :: g
        integer, intent(in) :: kind                 !! 1 .. NKINDS
        character(len=*), intent(in) :: analysis    !! its sweep: probe, chart, design, ...
        character(len=:), allocatable, intent(out) :: out
        integer, intent(out) :: expect
        character(len=:), allocatable, intent(out) :: note
        character(len=:), allocatable :: rec, body
        integer :: idone, nrec, r, a, b, p, q, nv, col, n, m, c
        character(len=16) :: val
        out = s
        note = ''
        expect = EXP_ANY
        idone = line_index(s, 'done ')
        nrec = count_lines_of(s) - idone - 1        ! (the records, before 'end')
        nv = 0
        if (nrec > 0) then
            call line_span(s, idone + 1, a, b)
            nv = (b - a + 1 - index(s(a:b), ' ') + 1)/17 - 1
        end if
        r = idone + pick(g, max(nrec, 1))           ! a record's line
        select case (kind)
        case (1)                                    ! flip one hex digit (values or CRC)
            call line_span(s, r, a, b)
            p = a + index(s(a:b), ' ') - 1          ! the blank after the index
            q = p + pick(g, b - p)
            if (s(q:q) == ' ') q = q + 1
            c = index(HEX, s(q:q)) - 1
            n = pick(g, 15)
            out = s(1:q - 1)//HEX(mod(c + n, 16) + 1:mod(c + n, 16) + 1)//s(q + 1:)
            expect = EXP_ONE
        case (2, 3, 4, 5)                           ! NaN, Inf or out of range in one value
            col = pick(g, nv)
            select case (kind)
            case (2, 3)                             ! a quiet or a signalling NaN
                val = merge('7FF8000000000000', '7FF0000000000001', pick(g, 2) == 1)
            case (4)
                val = merge('7FF0000000000000', 'FFF0000000000000', pick(g, 2) == 1)
            case default
                val = 'BFF8000000000000'            ! -1.5: in no sweep's range
                col = range_column(analysis, nv)
            end select
            call line_span(s, r, a, b)
            p = a + index(s(a:b), ' ') - 1 + 17*(col - 1) + 1
            rec = s(a:p - 1)//val//s(p + 16:b)
            if (kind /= 3) rec = sealed(rec)
            out = s(1:a - 1)//rec//s(b + 1:)
            expect = EXP_ONE
        case (6)                                    ! cut short at any byte
            out = s(1:pick(g, len(s)) - 1)
        case (7)                                    ! random bytes inserted
            p = pick(g, len(s))
            n = pick(g, 20)
            body = ''
            do m = 1, n
                c = pick(g, 256) - 1
                body = body//achar(c)
            end do
            out = s(1:p - 1)//body//s(p:)
        case (8)                                    ! a record twice
            call line_span(s, r, a, b)
            out = s(1:b + 1)//s(a:b + 1)//s(b + 2:)
        case (9)                                    ! two records swapped
            if (nrec >= 2) then
                r = idone + pick(g, nrec - 1)
                call line_span(s, r, a, b)
                call line_span(s, r + 1, p, q)
                out = s(1:a - 1)//s(p:q)//NL//s(a:b)//s(q + 1:)
                expect = EXP_ONE
            end if
        case (10)                                   ! the done count
            call line_span(s, idone, a, b)
            select case (pick(g, 5))
            case (1)
                body = 'done '//itoa(nrec - 1)
            case (2)
                body = 'done '//itoa(nrec + 1)
            case (3)
                body = 'done 0'
            case (4)
                body = 'done x'
            case default
                body = 'done '//itoa(100000000)
            end select
            out = s(1:a - 1)//body//s(b + 1:)
        case (11, 12)                               ! the deck's or the executable's CRC
            call line_span(s, line_index(s, merge('deck_crc64 ', 'exe_crc64  ', &
                           kind == 11)), a, b)
            q = b - pick(g, 16) + 1
            c = index(HEX, s(q:q)) - 1
            out = s(1:q - 1)//HEX(mod(c + 5, 16) + 1:mod(c + 5, 16) + 1)//s(q + 1:)
            expect = EXP_NOTE
            note = merge('another deck      ', 'another executable', kind == 11)
            note = trim(note)
        case (13)                                   ! another analysis
            call line_span(s, line_index(s, 'analysis '), a, b)
            out = s(1:b)//'x'//s(b + 1:)
            expect = EXP_NOTE
            note = 'another analysis'
        case (14)                                   ! another number of points
            call line_span(s, line_index(s, 'points '), a, b)
            out = s(1:b)//'0'//s(b + 1:)
            expect = EXP_NOTE
            note = 'another sweep'
        case (15)                                   ! another format
            call line_span(s, line_index(s, 'format '), a, b)
            out = s(1:a - 1)//'format 1'//s(b + 1:)
            expect = EXP_NOTE
            note = 'another format'
        case (16)                                   ! CR LF line ends
            out = ''
            a = 1
            do
                p = index(s(a:), NL)
                if (p == 0) exit
                out = out//s(a:a + p - 2)//achar(13)//NL
                a = a + p
            end do
            expect = EXP_NOTE
            note = 'another format'
        case (17)                                   ! empty
            out = ''
            expect = EXP_NOTE
            note = 'damaged'
        case (18)                                   ! far larger than the sweep's can be
            out = s//repeat('A', 200000)//NL
            expect = EXP_NOTE
            note = 'larger than'
        case (19)                                   ! a value more in a record
            call line_span(s, r, a, b)
            rec = s(a:b)//' 0000000000000000'
            if (pick(g, 2) == 1) rec = sealed(rec)
            out = s(1:a - 1)//rec//s(b + 1:)
            expect = EXP_ONE
        case (20)                                   ! a blank line among the records
            call line_span(s, r, a, b)
            out = s(1:a - 1)//NL//s(a:)
        case default                                ! no comment line
            call line_span(s, 1, a, b)
            out = s(b + 2:)
            expect = EXP_NOTE
            note = 'damaged'
        end select
    end subroutine mutate

    !> The value of a sweep's point whose range its check knows: -1.5 there is refused.
    integer function range_column(analysis, nv) result(col)
        character(len=*), intent(in) :: analysis
        integer, intent(in) :: nv
        select case (analysis)
        case ('probe')
            col = 2                                 ! sqrt(i)
        case ('identify_mc')
            col = nv                                ! the status code (0)
        case default
            col = 1                                 ! modulus, edge, period
        end select
    end function range_column

    !> A record line with its checksum made anew (the CRC-64 of its text before it).
    function sealed(rec) result(r)
        character(len=*), intent(in) :: rec
        character(len=:), allocatable :: r
        integer :: m
        m = len(rec)
        r = rec(1:m - 16)//hex16(crc64_of(rec(1:m - 17)))
    end function sealed

    ! =======================================================================================
    ! runs and files

    !> The uninterrupted run of deck into ref (exit 0, files written).
    subroutine make_reference(exe, deck, ref, d, ok)
        character(len=*), intent(in) :: exe, deck, ref, d
        logical, intent(out) :: ok
        integer :: ex
        call execute_command_line('rm -rf '//ref)
        ex = run(exe//' '//deck//' --out '//ref, d)
        ok = all([ex == 0, count_lines(d//'/stdout') == 1])
    end subroutine make_reference

    !> The five checkpoints of ALL_DECK or SWEEP_DECK, whole, in seed: a run with
    !! --checkpoint 0 whose commit fails (NAME.chart.dat is a folder) keeps them.
    subroutine make_full_checkpoints(exe, deck, seed, d, ok)
        character(len=*), intent(in) :: exe, deck, seed, d
        logical, intent(out) :: ok
        integer :: ex, w
        call execute_command_line('rm -rf '//seed//' && mkdir -p '//seed//'/all.chart.dat')
        ex = run(exe//' '//deck//' --out '//seed//' --checkpoint 0', d)
        call execute_command_line('rmdir '//seed//'/all.chart.dat')
        ok = ex == 5
        do w = 1, NSWEEPS
            if (ok) ok = file_has(seed//'/all.'//trim(SWEEPS(w))//'.partial', 'end')
        end do
    end subroutine make_full_checkpoints

    !> A run that finished: one stdout line, nothing on stderr, the files of ref (but
    !! cpu_seconds), nothing left (no checkpoint, no temporary file), no NaN.
    logical function finished_ok(o, ref) result(ok)
        character(len=*), intent(in) :: o, ref
        character(len=:), allocatable :: d
        d = o//'/..'
        ok = all([count_lines(d//'/stdout') == 1, message_lines(d//'/stderr') == 0, &
                  same_outputs(o, ref, d), clean(o, d), no_nan(o)])
    end function finished_ok

    !> The files of a and b are the same, names and bytes, but checkpoints (*.partial), the
    !! cpu_seconds lines and a certificate's foot (the date of its run).
    logical function same_outputs(a, b, d) result(same)
        character(len=*), intent(in) :: a, b, d
        integer :: ex
        ex = -1
        call execute_command_line('[ "$(ls '//a//' | grep -v ''\.partial$'')" = "$(ls '//b// &
            ' | grep -v ''\.partial$'')" ] && for f in $(ls '//b//'); do grep -v -e '// &
            '''^cpu_seconds'' -e ''^<footer>'' '//a//'/$f > '//d//'/cmp_a; grep -v -e '// &
            '''^cpu_seconds'' -e ''^<footer>'' '//b//'/$f > '//d//'/cmp_b; cmp -s '//d// &
            '/cmp_a '//d//'/cmp_b || exit 1; done', &
            exitstat=ex)
        same = ex == 0
    end function same_outputs

    !> No checkpoint and no temporary file in folder o.
    logical function clean(o, d)
        character(len=*), intent(in) :: o, d
        clean = shell_count('ls -A '//o//' | grep -c -e ''\.partial$'' -e ''\.tmp\.''', d) == 0
    end function clean

    !> Nothing in folder o but checkpoints (no temporary file, no output file).
    logical function clean_but_checkpoints(o, d) result(ok)
        character(len=*), intent(in) :: o, d
        ok = shell_count('ls -A '//o//' | grep -v -c ''\.partial$''', d) == 0
    end function clean_but_checkpoints

    !> Every path under folder base, one per line (what --out may create).
    function listing(base, d) result(s)
        character(len=*), intent(in) :: base, d
        character(len=:), allocatable :: s
        call execute_command_line('find '//base//' | sort > '//d//'/listing')
        s = read_file(d//'/listing')
    end function listing

    !> The bytes of a file ('' when it cannot be read).
    function read_file(path) result(s)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: s
        integer :: u, ios
        integer(int64) :: n
        s = ''
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        inquire (unit=u, size=n)
        if (n > 0) then
            deallocate (s)
            allocate (character(len=n) :: s)
            read (u, iostat=ios) s
            if (ios /= 0) s = ''
        end if
        close (u)
    end function read_file

    !> A file made of these bytes (replaced).
    subroutine write_file(path, s)
        character(len=*), intent(in) :: path, s
        integer :: u, ios
        call execute_command_line('rm -f '//path)
        open (newunit=u, file=path, status='replace', action='write', access='stream', &
              form='unformatted', iostat=ios)
        if (ios /= 0) return
        if (len(s) > 0) write (u, iostat=ios) s
        close (u)
    end subroutine write_file

    !> The k-th line of s (1 ...): its first and last character, a = 0 when there is none.
    subroutine line_span(s, k, a, b)
        character(len=*), intent(in) :: s
        integer, intent(in) :: k
        integer, intent(out) :: a, b
        integer :: j, p
        a = 1
        do j = 1, k - 1
            p = index(s(a:), NL)
            if (p == 0) then
                a = 0
                b = -1
                return
            end if
            a = a + p
        end do
        if (a > len(s)) then
            a = 0
            b = -1
            return
        end if
        p = index(s(a:), NL)
        b = len(s)
        if (p > 0) b = a + p - 2
    end subroutine line_span

    !> The number of the first line of s that starts with prefix (0 when none).
    integer function line_index(s, prefix) result(k)
        character(len=*), intent(in) :: s, prefix
        integer :: a, b, j
        k = 0
        do j = 1, count_lines_of(s)
            call line_span(s, j, a, b)
            if (a == 0) exit
            if (b - a + 1 >= len_trim(prefix)) then
                if (s(a:a + len_trim(prefix) - 1) == trim(prefix)) then
                    k = j
                    return
                end if
            end if
        end do
    end function line_index

    !> The number of lines of s (a last line without its newline counts).
    integer function count_lines_of(s) result(n)
        character(len=*), intent(in) :: s
        integer :: i
        n = 0
        do i = 1, len(s)
            if (s(i:i) == NL) n = n + 1
        end do
        if (len(s) > 0) then
            if (s(len(s):len(s)) /= NL) n = n + 1
        end if
    end function count_lines_of

    !> A draw in 1 .. n.
    integer function pick(g, n)
        type(rng_t), intent(inout) :: g
        integer, intent(in) :: n
        real(dp) :: u
        u = rng_uniform(g)
        pick = min(n, max(1, ceiling(u*n)))
    end function pick

    !> Seconds with three decimals, for sleep(1).
    function fixed3(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=16) :: buf
        write (buf, '(f0.3)') max(0.0_dp, x)
        s = trim(adjustl(buf))
        if (s(1:1) == '.') s = '0'//s
    end function fixed3

end module test_fuzz_resume
