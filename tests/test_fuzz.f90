!> The fuzz test: about 2000 hostile decks (24 of analysis tensor with their tables of
!! hangs mutated; 48 of the measurement inputs: tables of releases with sessions and
!! per-release settings, calibrations, platforms, records by column name or frame rate),
!! each a mutation of a shipped deck made
!! small (every group, the analyses, the model, broken structure, random bytes, mutated
!! records of analysis identify), run through the executable in batches; every deck ends in
!! one line, a finished one with its files whole, a failed one with nothing left.
module test_fuzz
    use, intrinsic :: iso_fortran_env, only: compiler_options
    use kinds, only: dp
    use status, only: status_t
    use testing, only: tester_t, write_text, file_has, count_lines, no_nan, upper, fresh_dir, &
        children_cpu_seconds
    use text, only: itoa
    use monte_carlo, only: MC_ANALYSIS
    use design, only: DESIGN_STAGES
    use deck, only: deck_t, read_deck, deck_echo, OUTPUT_COLUMNS
    use deck_runs, only: read_record
    use records, only: record_t
    use test_fuzz_tables, only: scale_column, insert_bytes, file_text
    implicit none
    private

    public :: run_fuzz_tests

    character(len=*), parameter :: SCRATCH = 'build/test_fuzz'

    !> Fuzz test: the seeds of the generator, decks per seed, decks per run of the program,
    !! and the hang check: seconds for a batch, then for one deck alone.
    integer, parameter :: FUZZ_SEEDS(4) = [20261121, 1966, 4242, 31337]
    integer, parameter :: FUZZ_PER_SEED = 520
    integer, parameter :: FUZZ_BATCH = 40
    integer, parameter :: FUZZ_BATCH_SECONDS = 120, FUZZ_DECK_SECONDS = 10
    !> The rule: a small deck ends within FUZZ_SMALL_SECONDS or has said on one line
    !! ('bifilar: note:') what it does and how long it takes.  Seconds of CPU time, which
    !! the load of the machine does not inflate: a batch that used more than that is run
    !! again deck by deck on one thread under a CPU-time limit of FUZZ_SMALL_SECONDS
    !! (`ulimit -S -t`; the program's note comes after 5 s of wall time, never later than
    !! that CPU time), and a deck cut off there must have printed its note.  (In the
    !! checking build, -fcheck=all and no optimisation, three times as long.)
    integer, parameter :: FUZZ_SMALL_SECONDS = 10
    !> Decks of analysis tensor (input/tensor_example.nml made small: &tensor and its
    !! table of hangs mutated), after the seeds' decks, FUZZ_TENSOR_BATCH at a time (a
    !! tensor deck takes about 0.5 s, 2 s in the checking build).
    integer, parameter :: FUZZ_TENSOR = 24, FUZZ_TENSOR_BATCH = 8
    !> Decks of the measurement inputs (write_measure_deck: tables of releases with sessions
    !! and per-release settings, calibrations, platforms, records with named columns or a
    !! frame rate), after the tensor decks, FUZZ_MEASURE_BATCH at a time.
    integer, parameter :: FUZZ_MEASURE = 48, FUZZ_MEASURE_BATCH = 8
    !> The groups of a deck, in the order the fuzz test writes them.
    integer, parameter :: NGROUPS = 12
    character(len=12), parameter :: GROUPS(NGROUPS) = [character(len=12) :: 'scene', &
        'suspension', 'body', 'start', 'integration', 'cables', 'floquet', 'chart', 'output', &
        'design', 'damping', 'measurement']
    integer, parameter :: GR_SCENE = 1, GR_SUSPENSION = 2, GR_BODY = 3, GR_START = 4, &
        GR_INTEGRATION = 5, GR_CABLES = 6, GR_FLOQUET = 7, GR_CHART = 8, GR_OUTPUT = 9, &
        GR_DESIGN = 10, GR_DAMPING = 11, GR_MEASUREMENT = 12
    !> The analyses the fuzz test must see finish (identify from periods and from a record).
    integer, parameter :: NRAN = 8
    character(len=16), parameter :: RAN_NAMES(NRAN) = [character(len=16) :: 'simulate', &
        'floquet', 'chart', 'work_precision', 'design', 'identify periods', 'identify record', &
        'tensor']
    !> The fuzz decks' record: the shipped record's first FUZZ_RECORD_SPAN seconds, every
    !! FUZZ_RECORD_EVERY-th sample (50 samples); Monte Carlo of at most FUZZ_MC_MAX samples.
    character(len=*), parameter :: FUZZ_RECORD = 'rec_base.dat'
    real(dp), parameter :: FUZZ_RECORD_SPAN = 2.0_dp
    integer, parameter :: FUZZ_RECORD_EVERY = 4
    integer, parameter :: FUZZ_MC_MAX = 3
    !> A deck as its group lines (the fuzz test's bases).
    type :: base_t
        character(len=16384) :: grp(NGROUPS) = ''
    end type base_t

contains

    subroutine run_fuzz_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('extreme: fuzzed hostile decks')) call fuzz_decks(t, exe)
    end subroutine run_fuzz_tests

    ! ---------------------------------------------------------------------------------------
    !> Fuzz test: FUZZ_PER_SEED mutated decks for each seed of FUZZ_SEEDS, made
    !! from every shipped deck (input/*.nml, input/extreme/*.nml, input/more/*.nml) kept
    !! small (load_bases) and then mutated: hostile, random, nearby and long values for the
    !! variables of all twelve groups, groups left out, decks cut short, random bytes, broken
    !! structure (unknown, duplicated and unterminated groups, subscripts left open at a line
    !! end, repeat counts), the analyses and the model changed, and the records of analysis
    !! identify mutated (write_fuzz_record).  The decks run FUZZ_BATCH at a time through one
    !! `bifilar deck ... --out DIR`, every other batch with `--checkpoint 0` so that the
    !! sweeps (chart, design) write their checkpoints, under a generous `timeout`; a batch
    !! that times out or takes a signal is run again deck by deck under `timeout`
    !! FUZZ_DECK_SECONDS to name the deck.  For every deck: no signal and no run-time error;
    !! exactly one line, on stdout 'NAME: ...' when it ran or on stderr 'bifilar: error
    !! (KIND): PATH: ...' when it failed; no file of a failed deck left, temporary files
    !! included (with --checkpoint 0 a sweep's checkpoint NAME.SWEEP.partial may stay, as
    !! documented: doc/output.md); no temporary file and
    !! no checkpoint left by a deck that finished; every analysis of a finished deck wrote
    !! its files, none empty or cut short (note_ran); no NaN, Inf or '****' in any file
    !! written; the batch's exit status the worst of its decks'.  And the decks cover every
    !! group and every analysis (each finished at least once; identify from periods and
    !! from a record).  The decks are the same in every build and on every machine.
    subroutine fuzz_decks(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(base_t), allocatable :: bases(:)
        type(record_t) :: rec
        integer(8) :: state
        integer :: is, k, kb, ndeck, nbad(8), counts(0:5), worst, ex, nb, j, mutated(NGROUPS)
        integer :: ran(NRAN), kept, nslow, ntensor_mut, small_seconds, nmeasure_kind(4)
        character(len=:), allocatable :: cal_text
        logical :: ckpt
        character(len=*), parameter :: dir = SCRATCH, outdir = dir//'/out'
        character(len=64) :: names(FUZZ_BATCH)
        character(len=256) :: paths(FUZZ_BATCH)
        character(len=200) :: first_bad(8)
        character(len=:), allocatable :: list
        character(len=*), parameter :: WHAT(8) = [character(len=60) :: &
            'a signal, a run-time error or a hang', 'not exactly one line naming the deck', &
            'a file of a failed deck left', 'NaN, Inf or **** written', &
            'exit status not the worst of the decks''', 'a kind of error that is no exit status', &
            'a finished analysis''s file missing, empty or cut short', &
            'past 10 s of CPU with no ''bifilar: note:'' line']
        call fresh_dir(dir)
        call load_bases(dir, bases, rec)
        call t%check('fuzz: shipped decks to mutate (at least 30)', size(bases) >= 30)
        call t%check('fuzz: the record of input/identify_record.nml read', allocated(rec%t))
        if (size(bases) == 0 .or. .not. allocated(rec%t)) return
        nbad = 0
        counts = 0
        first_bad = ''
        mutated = 0
        ran = 0
        kept = 0
        ndeck = 0
        nslow = 0
        small_seconds = FUZZ_SMALL_SECONDS
        if (index(compiler_options(), 'fcheck') > 0) small_seconds = 3*FUZZ_SMALL_SECONDS
        ntensor_mut = 0
        do is = 1, size(FUZZ_SEEDS)
            state = FUZZ_SEEDS(is)
            do kb = 1, FUZZ_PER_SEED, FUZZ_BATCH
                nb = min(FUZZ_BATCH, FUZZ_PER_SEED - kb + 1)
                do j = 1, nb
                    k = kb + j - 1
                    names(j) = 'fz'//itoa(is)//'_'//itoa(k)
                    paths(j) = dir//'/'//trim(names(j))//'.nml'
                    call write_fuzz_deck(dir, trim(names(j)), bases(1 + int(size(bases)* &
                                         rnd(state))), rec, state, mutated)
                end do
                ndeck = ndeck + nb
                ckpt = mod((kb - 1)/FUZZ_BATCH, 2) == 1
                call run_batch(nb)
            end do
        end do
        ! analysis tensor: its deck made small, &tensor and the table of hangs mutated
        do kb = 1, FUZZ_TENSOR, FUZZ_TENSOR_BATCH
            nb = min(FUZZ_TENSOR_BATCH, FUZZ_TENSOR - kb + 1)
            do j = 1, nb
                names(j) = 'ft_'//itoa(kb + j - 1)
                paths(j) = dir//'/'//trim(names(j))//'.nml'
                call write_tensor_deck(dir, trim(names(j)), state, ntensor_mut)
            end do
            ndeck = ndeck + nb
            ckpt = .false.
            call run_batch(nb)
        end do
        write (*, '(a,i0,a,i0,a)') '   fuzz: ', FUZZ_TENSOR, ' of them tensor decks (', &
            ntensor_mut, ' with &tensor or the table of hangs mutated)'
        ! the measurement inputs: tables with sessions and settings, calibrations,
        ! platforms, records with named columns or a frame rate
        call execute_command_line(exe//' input/calibrate_example.nml --out '//dir// &
                                  '/calib > /dev/null 2>&1')
        cal_text = file_text(dir//'/calib/calibrate_example.calibration')
        nmeasure_kind = 0
        do kb = 1, FUZZ_MEASURE, FUZZ_MEASURE_BATCH
            nb = min(FUZZ_MEASURE_BATCH, FUZZ_MEASURE - kb + 1)
            do j = 1, nb
                names(j) = 'fm_'//itoa(kb + j - 1)
                paths(j) = dir//'/'//trim(names(j))//'.nml'
                call write_measure_deck(dir, trim(names(j)), rec, cal_text, state, &
                                        nmeasure_kind)
            end do
            ndeck = ndeck + nb
            ckpt = .false.
            call run_batch(nb)
        end do
        write (*, '(a,i0,a,4(i0,a))') '   fuzz: ', FUZZ_MEASURE, ' measurement decks (', &
            nmeasure_kind(1), ' tables with sessions, ', nmeasure_kind(2), ' calibrations, ', &
            nmeasure_kind(3), ' platforms, ', nmeasure_kind(4), ' records by column name or '// &
            'frame rate)'
        write (*, '(a,i0,a,i0,a)') '   fuzz: ', nslow, ' decks ran past ', &
            small_seconds, ' s of CPU alone (each must have said so on a note line)'
        write (*, '(a,i0,a,i0,a,6(i0,a))') '   fuzz: ', ndeck, ' decks from ', size(bases), &
            ' shipped decks; exit 0: ', counts(0), ', 2: ', counts(2), ', 3: ', counts(3), &
            ', 4: ', counts(4), ', 5: ', counts(5), ', other: ', counts(1), ''
        list = ''
        do j = 1, NRAN
            list = list//', '//trim(RAN_NAMES(j))//' '//itoa(ran(j))
        end do
        write (*, '(a)') '   fuzz: finished '//list(3:)
        list = ''
        do j = 1, NGROUPS
            list = list//', '//trim(GROUPS(j))//' '//itoa(mutated(j))
        end do
        write (*, '(a)') '   fuzz: mutations per group: '//list(3:)
        write (*, '(a,i0,a)') '   fuzz: ', kept, ' checkpoints kept by decks that failed '// &
            'after their sweep (--checkpoint 0)'
        do j = 1, size(nbad)
            call t%check('fuzz: '//trim(WHAT(j))//': '//itoa(nbad(j))//' decks '// &
                         trim(first_bad(j)), nbad(j) == 0)
        end do
        call t%check('fuzz: at least 2000 decks', ndeck >= 2000)
        call t%check('fuzz: tensor decks mutated', ntensor_mut > 0)
        call t%check('fuzz: every kind of measurement deck written', all(nmeasure_kind > 0))
        call t%check('fuzz: every group mutated', all(mutated > 0))
        call t%check('fuzz: every analysis finished at least once', all(ran > 0))
        call t%check('fuzz: some decks run, some are refused', counts(0) > 0 .and. counts(2) > 0)
        if (all(nbad == 0)) call execute_command_line('rm -rf '//dir)

    contains

        !> Run decks 1..n in one process, then check every deck's line and files.
        subroutine run_batch(n)
            integer, intent(in) :: n
            character(len=:), allocatable :: cmd
            integer :: i, st, w, wk, wt
            logical :: one_line
            character(len=:), allocatable :: kind
            real(dp) :: cpu0, cpu1
            call fresh_dir(outdir)
            cmd = 'timeout '//itoa(FUZZ_BATCH_SECONDS)//' '//exe
            do i = 1, n
                cmd = cmd//' '//trim(paths(i))
            end do
            if (ckpt) cmd = cmd//' --checkpoint 0'
            ex = -1
            cpu0 = children_cpu_seconds()
            call execute_command_line(cmd//' --out '//outdir//' > '//dir//'/stdout 2> '// &
                                      dir//'/stderr', exitstat=ex)
            cpu1 = children_cpu_seconds()
            if (abnormal(ex, dir//'/stderr')) then
                call rerun_alone(n)
                return
            end if
            if (cpu1 - cpu0 > small_seconds) then
                call slow_alone(n)
                call fresh_dir(outdir)
                call execute_command_line(cmd//' --out '//outdir//' > '//dir//'/stdout 2> '// &
                                          dir//'/stderr', exitstat=ex)
            end if
            call execute_command_line('ls -a '//outdir//' > '//dir//'/listing')
            ! the files that are empty or do not end with a line end (cut short)
            call execute_command_line('cd '//outdir//' && for f in *; do [ -f "$f" ] || '// &
                'continue; if [ ! -s "$f" ] || [ -n "$(tail -c 1 "$f")" ]; then echo "$f"; '// &
                'fi; done > ../cut_short')
            worst = 0
            do i = 1, n
                kind = ''
                ! (a note or a warning is a line beside the deck's one line)
                one_line = count_lines(dir//'/stdout', trim(names(i))//': ', .true.) + &
                    error_lines(i) == 1
                if (error_lines(i) == 1) &
                    kind = error_kind(dir//'/stderr', ': '//trim(paths(i))//': ')
                if (.not. one_line) call bad(2, trim(names(i)))
                st = 0
                select case (kind)
                case ('')
                    st = 0
                    call note_ran(trim(names(i)))
                case ('bad input')
                    st = 2
                case ('numerical failure')
                    st = 3
                case ('model no longer valid')
                    st = 4
                case ('cannot write output')
                    st = 5
                case default
                    st = 1
                    call bad(6, trim(names(i))//' '//kind)
                end select
                counts(st) = counts(st) + 1
                worst = max(worst, st)
                ! nothing of a failed deck is left but (--checkpoint 0) its sweeps'
                ! checkpoints; a finished deck leaves no temporary file and no checkpoint
                call leftovers(trim(names(i)), w, wk, wt)
                if (st /= 0) then
                    if (.not. ckpt) wk = 0
                    kept = kept + wk
                    if (w /= wk) call bad(3, trim(names(i)))
                else if (wt > 0) then
                    call bad(3, trim(names(i))//' (finished)')
                end if
            end do
            if (count_lines(dir//'/stderr') /= nfailed_lines(n)) &
                call bad(2, 'batch '//trim(names(1))//': stray stderr line '''// &
                         stray_line(n)//'''')
            if (ex /= worst) call bad(5, 'batch '//trim(names(1))//' exit '//itoa(ex)// &
                                      ' worst '//itoa(worst))
            if (.not. no_nan(outdir)) call bad(4, 'batch '//trim(names(1)))
        end subroutine run_batch

        !> A batch that took a signal, printed a run-time error or timed out: each deck
        !! alone under timeout FUZZ_DECK_SECONDS, to name the culprit.
        subroutine run_batch_alone_one(i, culprit)
            integer, intent(in) :: i
            logical, intent(out) :: culprit
            integer :: e
            call fresh_dir(outdir)
            e = -1
            call execute_command_line('timeout '//itoa(FUZZ_DECK_SECONDS)//' '//exe//' '// &
                                      trim(paths(i))//' --out '//outdir//' > '//dir// &
                                      '/stdout 2> '//dir//'/stderr', exitstat=e)
            culprit = abnormal(e, dir//'/stderr')
        end subroutine run_batch_alone_one

        !> A batch that used more than FUZZ_SMALL_SECONDS of CPU time: each deck alone, on
        !! one thread, under a CPU-time limit of FUZZ_SMALL_SECONDS (SIGXCPU, exit 152;
        !! SIGKILL, 137, past a hard limit) and, for a deck that waits without computing,
        !! the batch's timeout (124); one cut off must have said what it does on a note line.
        subroutine slow_alone(n)
            integer, intent(in) :: n
            integer :: i, e
            do i = 1, n
                call fresh_dir(outdir)
                e = -1
                call execute_command_line('ulimit -c 0; ulimit -S -t '//itoa(small_seconds)// &
                    '; OMP_NUM_THREADS=1 timeout '//itoa(FUZZ_BATCH_SECONDS)//' '//exe// &
                    ' '//trim(paths(i))//' --out '//outdir//' > '//dir//'/stdout 2> '//dir// &
                    '/stderr', exitstat=e)
                if (e == 124 .or. e == 137 .or. e == 152) then
                    nslow = nslow + 1
                    if (count_lines(dir//'/stderr', 'bifilar: note: '//trim(paths(i))//': ', &
                                    .true.) /= 1) call bad(8, trim(names(i)))
                end if
            end do
        end subroutine slow_alone

        subroutine rerun_alone(n)
            integer, intent(in) :: n
            integer :: i
            logical :: culprit, any_culprit
            any_culprit = .false.
            do i = 1, n
                call run_batch_alone_one(i, culprit)
                if (culprit) call bad(1, trim(names(i)))
                any_culprit = any_culprit .or. culprit
            end do
            if (.not. any_culprit) call bad(1, 'batch '//trim(names(1))//' exit '//itoa(ex)// &
                                            ' (no deck alone)')
            counts(1) = counts(1) + n
        end subroutine rerun_alone

        !> Files of deck nm in the batch's output folder (dir/listing): all of them (w), its
        !! sweeps' checkpoints NAME.SWEEP.partial (wk), its temporary files and checkpoints
        !! NAME.*.tmp.*, NAME.*.partial (wt).
        subroutine leftovers(nm, w, wk, wt)
            character(len=*), intent(in) :: nm
            integer, intent(out) :: w, wk, wt
            character(len=*), parameter :: SWEEPS(5) = [character(len=16) :: 'chart', &
                DESIGN_STAGES, MC_ANALYSIS]
            character(len=1024) :: line
            integer :: u, ios, k
            w = 0
            wk = 0
            wt = 0
            open (newunit=u, file=dir//'/listing', status='old', action='read', iostat=ios)
            do while (ios == 0)
                read (u, '(a)', iostat=ios) line
                if (ios /= 0) exit
                if (index(line, nm//'.') /= 1) cycle
                w = w + 1
                k = len_trim(line)
                if (index(line, '.tmp.') > 0 .or. index(line, '.partial', back=.true.) == &
                    k - 7) wt = wt + 1
                do k = 1, size(SWEEPS)
                    if (trim(line) == nm//'.'//trim(SWEEPS(k))//'.partial') wk = wk + 1
                end do
            end do
            close (u)
        end subroutine leftovers

        !> Lines of the batch's stderr that name deck i, its notes and warnings left out.
        integer function error_lines(i)
            integer, intent(in) :: i
            error_lines = count_lines(dir//'/stderr', ': '//trim(paths(i))//': ', .false.) - &
                count_lines(dir//'/stderr', 'bifilar: note: '//trim(paths(i))//': ', .true.) - &
                count_lines(dir//'/stderr', 'bifilar: warning: '//trim(paths(i))//': ', .true.)
        end function error_lines

        !> Lines of the batch's stderr that belong to some deck of the batch.
        integer function nfailed_lines(n)
            integer, intent(in) :: n
            integer :: i
            nfailed_lines = 0
            do i = 1, n
                nfailed_lines = nfailed_lines + count_lines(dir//'/stderr', ': '// &
                    trim(paths(i))//': ', .false.)
            end do
        end function nfailed_lines

        !> The first line of the batch's stderr that names none of its decks.
        function stray_line(n) result(s)
            integer, intent(in) :: n
            character(len=:), allocatable :: s
            character(len=8192) :: line
            integer :: u, ios, i
            logical :: named
            s = ''
            open (newunit=u, file=dir//'/stderr', status='old', action='read', iostat=ios)
            do while (ios == 0)
                read (u, '(a)', iostat=ios) line
                if (ios /= 0) exit
                named = .false.
                do i = 1, n
                    if (index(line, ': '//trim(paths(i))//': ') > 0) named = .true.
                end do
                if (.not. named) then
                    s = trim(line(1:min(len_trim(line), 120)))
                    exit
                end if
            end do
            close (u)
        end function stray_line

        !> A finished deck: which analyses it ran (from its line on stdout; identify's mode
        !! from its .identify file); each of them wrote its file (simulate NAME.dat and
        !! NAME.summary, floquet NAME.floquet, chart NAME.chart.dat, work_precision
        !! NAME.wp.dat, design NAME.design, identify NAME.identify and from a record
        !! NAME.fit.dat), and no file of the deck is empty or cut short (no line end last).
        subroutine note_ran(nm)
            character(len=*), intent(in) :: nm
            logical :: whole
            whole = count_lines(dir//'/cut_short', nm//'.', .true.) == 0
            if (line_with(dir//'/stdout', nm//': ', ' simulate cpu')) then
                ran(1) = ran(1) + 1
                if (.not. written_file(nm, '.dat')) whole = .false.
                if (.not. written_file(nm, '.summary')) whole = .false.
            end if
            if (line_with(dir//'/stdout', nm//': ', ' floquet period')) then
                ran(2) = ran(2) + 1
                if (.not. written_file(nm, '.floquet')) whole = .false.
            end if
            if (line_with(dir//'/stdout', nm//': ', ' chart ')) then
                ran(3) = ran(3) + 1
                if (.not. written_file(nm, '.chart.dat')) whole = .false.
            end if
            if (line_with(dir//'/stdout', nm//': ', ' work_precision ')) then
                ran(4) = ran(4) + 1
                if (.not. written_file(nm, '.wp.dat')) whole = .false.
            end if
            if (line_with(dir//'/stdout', nm//': ', ' design ')) then
                ran(5) = ran(5) + 1
                if (.not. written_file(nm, '.design')) whole = .false.
            end if
            if (line_with(dir//'/stdout', nm//': ', ' identify I1 = ')) then
                if (.not. written_file(nm, '.identify')) whole = .false.
                if (line_with(outdir//'/'//nm//'.identify', 'mode = ', 'periods')) &
                    ran(6) = ran(6) + 1
                if (line_with(outdir//'/'//nm//'.identify', 'mode = ', 'record')) then
                    ran(7) = ran(7) + 1
                    if (.not. written_file(nm, '.fit.dat')) whole = .false.
                end if
            end if
            if (line_with(dir//'/stdout', nm//': ', ' tensor I_principal')) then
                ran(8) = ran(8) + 1
                if (.not. written_file(nm, '.tensor')) whole = .false.
            end if
            if (.not. whole) call bad(7, nm)
        end subroutine note_ran

        !> Whether the batch's output folder holds file nm//ext.
        logical function written_file(nm, ext)
            character(len=*), intent(in) :: nm, ext
            written_file = count_lines(dir//'/listing', nm//ext, .true.) > 0
        end function written_file

        subroutine bad(kind, what)
            integer, intent(in) :: kind
            character(len=*), intent(in) :: what
            nbad(kind) = nbad(kind) + 1
            if (len_trim(first_bad(kind)) == 0) first_bad(kind) = '(first: '//what//')'
        end subroutine bad

    end subroutine fuzz_decks

    !> The shipped decks, read and made small: tau_end <= 2 with at most 40 rows, charts of
    !! at most 2 x 2 points, Floquet rtol >= 1e-8, designs of at most 3 x 2 candidates at 2
    !! amplitudes, Monte Carlo of at most FUZZ_MC_MAX samples, a record cut to its first
    !! FUZZ_RECORD_SPAN seconds (every FUZZ_RECORD_EVERY-th sample: dir/FUZZ_RECORD),
    !! work_precision left out (it times at least 0.05 s per point; the mutations put it back
    !! now and then).  Each as its group lines, all groups present but &output (absent when
    !! every column is written).  rec: the first FUZZ_RECORD_SPAN seconds of the shipped
    !! record, every sample (for write_fuzz_record).
    subroutine load_bases(dir, bases, rec)
        character(len=*), intent(in) :: dir
        type(base_t), allocatable, intent(out) :: bases(:)
        type(record_t), intent(out) :: rec
        type(deck_t) :: d
        type(record_t) :: full
        type(status_t) :: st
        character(len=512) :: path
        character(len=4096) :: line
        character(len=:), allocatable :: model, analyses
        integer :: u, v, ios, n, g, i1, i2
        d%measurement%record = 'input/identify_record_swing.dat'
        d%measurement%record_path = trim(d%measurement%record)
        call read_record(d, full, st)
        if (st%code /= 0) return
        n = count(full%t <= FUZZ_RECORD_SPAN)
        rec%t = full%t(1:n)
        rec%v = full%v(1:n)
        rec%u = full%u(1:n)
        call write_text(dir//'/'//FUZZ_RECORD, record_text(rec%t(1:n:FUZZ_RECORD_EVERY), &
                         rec%v(1:n:FUZZ_RECORD_EVERY), rec%u(1:n:FUZZ_RECORD_EVERY), 2, &
                         '', '', ' ', .true.))
        call execute_command_line('ls input/*.nml input/extreme/*.nml input/more/*.nml > '// &
                                  dir//'/bases.txt')
        allocate (bases(0))
        open (newunit=u, file=dir//'/bases.txt', status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) path
            if (ios /= 0) exit
            call read_deck(trim(path), d, st)
            if (st%code /= 0) cycle
            model = trim(d%scene%model)
            analyses = ''
            i2 = 0
            do
                i1 = i2 + verify(d%scene%analyses(i2 + 1:), ' ')
                if (i1 == i2 .or. i1 > len_trim(d%scene%analyses)) exit
                i2 = i1 + index(d%scene%analyses(i1:)//' ', ' ') - 2
                if (d%scene%analyses(i1:i2) /= 'work_precision') analyses = analyses//' '// &
                    d%scene%analyses(i1:i2)
            end do
            if (len(analyses) == 0) analyses = ' simulate'
            d%integration%tau_end = min(d%integration%tau_end, 2.0_dp)
            d%integration%dtau_out = max(d%integration%tau_end/40.0_dp, &
                                         min(d%integration%dtau_out, d%integration%tau_end))
            d%chart%nx = min(d%chart%nx, 2)
            d%chart%ny = min(d%chart%ny, 2)
            d%floquet%rtol = max(d%floquet%rtol, 1.0e-8_dp)
            d%design%nl = min(d%design%nl, 3)
            d%design%nb = min(d%design%nb, 2)
            d%design%n_amplitudes = min(d%design%n_amplitudes, 2)
            d%measurement%monte_carlo = min(d%measurement%monte_carlo, FUZZ_MC_MAX)
            if (len_trim(d%measurement%record) > 0) d%measurement%record = FUZZ_RECORD
            ! every group in the echo: elastic shows &cables, the analyses theirs
            d%scene%model = 'elastic'
            d%scene%analyses = 'floquet chart design identify'
            open (newunit=v, file=dir//'/echo.txt', status='replace', action='write')
            ios = 0
            call deck_echo(d, v, ios)
            close (v)
            n = size(bases) + 1
            bases = [bases, base_t()]
            open (newunit=v, file=dir//'/echo.txt', status='old', action='read')
            do
                read (v, '(a)', iostat=ios) line
                if (ios /= 0) exit
                if (index(line, '# &') /= 1) cycle
                do g = 1, NGROUPS
                    if (index(line, '# &'//trim(GROUPS(g))//' ') == 1) &
                        bases(n)%grp(g) = trim(line(3:))
                end do
            end do
            close (v)
            ios = 0
            bases(n)%grp(GR_SCENE) = "&scene title = 'fuzz', analyses = '"//analyses(2:)// &
                "', model = '"//model//"' /"
        end do
        close (u)
    end subroutine load_bases

    !> A mutated deck NAME.nml in dir from a base: 1 to 3 mutations of one of eleven kinds,
    !! the last (a mutated record, write_fuzz_record) twice as likely as each other.
    subroutine write_fuzz_deck(dir, name, base, rec, state, mutated)
        character(len=*), intent(in) :: dir, name
        type(base_t), intent(in) :: base
        type(record_t), intent(in) :: rec           !! the shipped record's first seconds
        integer(8), intent(inout) :: state
        integer, intent(inout) :: mutated(NGROUPS)       !! mutations per group so far
        type(base_t) :: b
        character(len=:), allocatable :: text, v, var, path
        integer :: kind, j, n, g, pos
        b = base
        path = dir//'/'//name//'.nml'
        kind = int(12*rnd(state))
        select case (kind)
        case (0, 1, 2, 3)
            ! one to three variables: hostile (0), random (1), nearby (2, 3) values
            n = 1 + int(3*rnd(state))
            do j = 1, n
                g = 1 + int(NGROUPS*rnd(state))
                var = pick_var(g, state)
                v = pick_value(var, kind, state)
                call set_var(b, g, var, v)
                mutated(g) = mutated(g) + 1
            end do
            call write_text(path, assemble(b%grp))
        case (4)
            ! groups left out (the group drawn first: gfortran -O3 evaluates a function in
            ! the subscript of a character assignment's left side twice, which made the
            ! optimised and the checking build fuzz different decks)
            do j = 1, 1 + int(3*rnd(state))
                g = 1 + int(NGROUPS*rnd(state))
                b%grp(g) = ''
            end do
            call write_text(path, assemble(b%grp))
        case (5)
            ! cut short
            text = assemble(b%grp)
            call write_text(path, text(1:int(len(text)*rnd(state))))
        case (6)
            ! random bytes inserted, or a deck of random bytes
            text = assemble(b%grp)
            if (rnd(state) < 0.8_dp) then
                do j = 1, 1 + int(5*rnd(state))
                    pos = 1 + int(len(text)*rnd(state))
                    text = text(1:pos - 1)//random_bytes(state, 1 + int(20*rnd(state)))// &
                        text(pos:)
                end do
            else if (rnd(state) < 0.5_dp) then
                text = random_bytes(state, int(3000*rnd(state)))
            else
                text = '&suspension '//random_bytes(state, 200)//' /'//new_line('a')// &
                    '&body '//random_bytes(state, 200)//' /'
            end if
            call write_text(path, text)
        case (7)
            ! structure: duplicated, unknown, unterminated groups, subscripts, repeat counts
            select case (int(13*rnd(state)))
            case (0)
                b%grp(GR_FLOQUET) = b%grp(GR_SUSPENSION)
            case (1)
                b%grp(GR_CHART) = '&nonsense x = 1 /'
            case (2)
                g = 1 + int(NGROUPS*rnd(state))
                b%grp(g) = b%grp(g)(1:max(0, len_trim(b%grp(g)) - 1))
            case (3)
                b%grp(GR_START) = "&start mode = 'angles', theta(7) = 1.0, theta_dot(0) = 2.0 /"
            case (4)
                call set_var(b, GR_BODY, 'btilde(4,1)', '1.0')
                call set_var(b, GR_BODY, 'inertia(-3)', '1')
            case (5)
                call set_var(b, GR_BODY, 'inertia', '1000000*0.1')
            case (6)
                ! a subscript left open at the end of a line (SIGSEGV before this was mended)
                b%grp(GR_BODY) = '&body inertia('//new_line('a')//'/'
            case (7)
                call set_var(b, GR_BODY, 'btilde(1,'//new_line('a')//'2)', '1')
            case (8)
                ! the newer groups twice, or one inside another's place
                b%grp(GR_CABLES) = b%grp(GR_MEASUREMENT)
                b%grp(GR_OUTPUT) = '&damping c_v = 1e-3 /'
            case (9)
                call set_var(b, GR_MEASUREMENT, 'periods(101)', '1.5')
                call set_var(b, GR_MEASUREMENT, 'amplitudes(0)', '10')
            case (10)
                call set_var(b, GR_MEASUREMENT, 'periods', '100*1.5, 1.6')
            case (11)
                call set_var(b, GR_MEASUREMENT, 'periods(3)', '1.5')
                call set_var(b, GR_MEASUREMENT, 'amplitudes(3)', '30')
            case default
                b%grp = ''
            end select
            call write_text(path, assemble(b%grp))
        case (8)
            ! the analyses and the model
            call set_var(b, GR_SCENE, 'analyses', pick_value('analyses', 1, state))
            if (rnd(state) < 0.3_dp) call set_var(b, GR_SCENE, 'model', &
                                                  pick_value('model', 1, state))
            mutated(GR_SCENE) = mutated(GR_SCENE) + 1
            call write_text(path, assemble(b%grp))
        case (9)
            ! a long value or a long line
            g = 1 + int(NGROUPS*rnd(state))
            var = pick_var(g, state)
            if (rnd(state) < 0.5_dp) then
                v = ''''//repeat('x', 100 + int(6000*rnd(state)))//''''
            else
                v = repeat('9', 50 + int(5000*rnd(state)))
            end if
            call set_var(b, g, var, v)
            mutated(g) = mutated(g) + 1
            call write_text(path, assemble(b%grp))
        case default
            ! a mutated record (a deck without one is made a record fit first)
            if (index(b%grp(GR_MEASUREMENT), 'record = ') == 0) then
                b%grp(GR_MEASUREMENT) = "&measurement record = '"//FUZZ_RECORD// &
                    "', quantity = 'rate', estimate = 'I1' /"
                call set_var(b, GR_SCENE, 'analyses', "'identify'")
                call set_var(b, GR_SCENE, 'model', "'kane'")
            end if
            call write_fuzz_record(dir, name, rec, state, v)
            call set_var(b, GR_MEASUREMENT, 'record', v)
            mutated(GR_MEASUREMENT) = mutated(GR_MEASUREMENT) + 1
            call write_text(path, assemble(b%grp))
        end select
    end subroutine write_fuzz_deck

    !> A tensor deck NAME.nml in dir from input/tensor_example.nml made small (Monte Carlo
    !! of at most FUZZ_MC_MAX samples), with its own table of hangs NAME.hangs.csv: as it
    !! is, or (nmut counts them) the table's periods in ms, totals without their cycles,
    !! directions with their sign flipped (both: the same hang; one: another), amplitudes
    !! in radians or scaled, cycles 0 or negative, random bytes, cut short, another file
    !! (a device, a folder, missing), or a value of &tensor, &suspension or &body hostile.
    subroutine write_tensor_deck(dir, name, state, nmut)
        character(len=*), intent(in) :: dir, name
        integer(8), intent(inout) :: state
        integer, intent(inout) :: nmut
        character(len=*), parameter :: NL = new_line('a')
        character(len=16), parameter :: HOSTILE(10) = [character(len=16) :: '-1', '0', &
            '1e100', '1e-300', 'NaN', '-0.0', '1e9', '2', '0.5', '3']
        character(len=16), parameter :: TVARS(9) = [character(len=16) :: 'u_mass', 'u_l', &
            'u_b_prime', 'u_period', 'u_amplitude', 'u_direction', 'monte_carlo', 'seed', &
            'plan']
        character(len=16), parameter :: RVARS(6) = [character(len=16) :: 'b', 'b_prime', &
            'l', 'mass', 'cg_depth', 'cg_offset']
        character(len=24), parameter :: ODD(5) = [character(len=24) :: '/dev/zero', '.', &
            'missing.csv', '/dev/null', '']
        character(len=:), allocatable :: table, hangs, sus, body, tens, v
        integer :: kind, i
        table = file_text('input/tensor_example_hangs.csv')
        hangs = name//'.hangs.csv'
        sus = "&suspension b = 0.60, b_prime = 0.50, l = 1.50, l_prime = 1.50, g = 9.80665"
        body = "&body mass = 4.2, inertia = 0.10, 0.12, 0.15, cg_depth = 0.12, cg_offset = 0.0"
        tens = ", u_mass = 0.001, u_l = 0.001, u_l_prime = 0.001, u_b = 0.0005, "// &
            "u_b_prime = 0.0005, u_g = 0, u_period = 1e-3, u_amplitude = 0.5, "// &
            "u_direction = 0.2, monte_carlo = "//itoa(int((FUZZ_MC_MAX + 1)*rnd(state)))
        kind = int(14*rnd(state))
        if (kind < 10) nmut = nmut + 1
        select case (kind)
        case (0)
            table = scale_column(table, 8, 1000.0_dp)
        case (1)
            table = scale_column(table, 8, 10.0_dp)
        case (2)
            table = scale_column(scale_column(table, 2 + int(3*rnd(state)), -1.0_dp), &
                                 5 + int(3*rnd(state)), -1.0_dp)
        case (3)
            table = scale_column(table, 2 + int(6*rnd(state)), -1.0_dp)
        case (4)
            table = scale_column(table, 10, merge(0.017453292519943295_dp, &
                                 10.0_dp**(int(4*rnd(state)) - 1), rnd(state) < 0.5_dp))
        case (5)
            table = scale_column(table, 9, real(int(3*rnd(state)) - 1, dp))
        case (6)
            do i = 1, 1 + int(3*rnd(state))
                call insert_bytes(table, state)
            end do
        case (7)
            table = table(1:int(len(table)*rnd(state)))
        case (8)
            hangs = trim(ODD(1 + int(size(ODD)*rnd(state))))
        case (9)
            v = trim(HOSTILE(1 + int(size(HOSTILE)*rnd(state))))
            select case (int(3*rnd(state)))
            case (0)
                tens = tens//', '//trim(TVARS(1 + int(size(TVARS)*rnd(state))))//' = '//v
            case (1)
                sus = sus//', '//trim(RVARS(1 + int(3*rnd(state))))//' = '//v
            case default
                body = body//', '//trim(RVARS(4 + int(3*rnd(state))))//' = '//v
            end select
        end select
        if (kind /= 8) call write_text(dir//'/'//name//'.hangs.csv', table)
        call write_text(dir//'/'//name//'.nml', "&scene title = 'fuzz tensor', "// &
            "analyses = 'tensor' /"//NL//sus//' /'//NL//body//' /'//NL//"&tensor hangs = '"// &
            hangs//"'"//tens//' /'//NL)
    end subroutine write_tensor_deck

    !> A deck NAME.nml in dir of the measurement inputs, each kind with its file written
    !! beside it (kinds counts them): a table of releases (input/identify_trials.csv's first
    !! rows) with columns session and estimate and &measurement on_failure; a deck timed on
    !! the rig of input/calibrate_example.nml with &measurement calibration = 'NAME.cal'
    !! (that deck's calibration, cal); the trifilar platform of
    !! input/measure_platform_template.nml, or a platform by support_points, body_points
    !! and lengths; the fuzz record with a header naming its columns (record_columns by
    !! name, a text column beside) or as frame numbers (record_frame_rate).  Each as it is,
    !! or with one value hostile, a row or cell changed, the file cut short, bytes inserted.
    subroutine write_measure_deck(dir, name, rec, cal, state, kinds)
        character(len=*), intent(in) :: dir, name, cal
        type(record_t), intent(in) :: rec
        integer(8), intent(inout) :: state
        integer, intent(inout) :: kinds(4)
        character(len=*), parameter :: NL = new_line('a')
        character(len=16), parameter :: HOSTILE(12) = [character(len=16) :: '-1', '0', &
            '1e100', '1e-300', 'NaN', '-0.0', '1e9', '2', '0.5', '3', '''''', '''x''']
        character(len=16), parameter :: SETTINGS(6) = [character(len=16) :: 'I1', &
            'I1 c_v', 'bogus', '', 'amplitude', 'I1 t0']
        character(len=:), allocatable :: head, table, meas, sus, body, file, v
        character(len=64) :: row
        real(dp) :: x
        integer :: kind, i, n, mut
        kind = int(4*rnd(state))
        kinds(kind + 1) = kinds(kind + 1) + 1
        mut = int(6*rnd(state))
        v = trim(HOSTILE(1 + int(size(HOSTILE)*rnd(state))))
        head = "&scene title = 'fuzz measurement', analyses = 'identify' /"//NL
        file = name//'.csv'
        select case (kind)
        case (0)
            ! a table of releases in two sessions, each release's estimate its own
            table = 'trial,l,l_prime,period,cycles,amplitude,session,estimate'//NL
            n = 1
            do i = 1, 8
                ! each release's estimate on both its rows; now and then another on one
                x = rnd(state)
                if (mod(i, 2) == 1) n = merge(1, 1 + int(6*x), mut /= 0)
                if (mut == 0 .and. x < 0.1_dp) n = 1 + int(60*x)
                write (row, '(a,i0,a,f0.2,a,a,a)') 'r', (i + 1)/2, ',1.2,1.2,', &
                    18.30_dp + 0.01_dp*mod(7*i, 9), ',10,10.0,s', merge('1', '2', i <= 4), ','
                table = table//trim(row)//trim(SETTINGS(n))//NL
            end do
            sus = '&suspension b = 0.25, b_prime = 0.25, l = 1.2, l_prime = 1.2, g = 9.80665 /'
            body = '&body mass = 8.1, inertia = 0.09, 0.0286875, 0.0624375, cg_depth = 0.025 /'
            meas = "&measurement trials = '"//file//"', u_period = 0.05, u_mass = 0.005, "// &
                "on_failure = '"//trim(merge('skip', 'stop', rnd(state) < 0.5_dp))//"'"
            select case (mut)
            case (1)
                table = scale_column(table, 4, 10.0_dp**(int(5*rnd(state)) - 2))
            case (2)
                meas = meas//', on_failure = '//v
            case (3)
                call insert_bytes(table, state)
            case (4)
                table = table(1:int(len(table)*rnd(state)))
            case (5)
                meas = meas//', session = '//v
            end select
        case (1)
            ! a calibrated rig
            file = name//'.cal'
            table = cal
            sus = '&suspension b = 0.4008, b_prime = 0.4008, l = 1.20, l_prime = 1.20, '// &
                'g = 9.80665 /'
            body = '&body mass = 3.10, inertia = 0.045, 0.0630, 0.0304, cg_depth = 0.15, '// &
                'cg_offset = 0.0 /'
            meas = "&measurement periods = 1.41564, 1.44107, amplitudes = 10, 30, "// &
                "u_period = 1e-4, u_mass = 0.001, calibration = '"//file//"'"
            select case (mut)
            case (1)
                n = index(table, 'scale = ')
                if (n > 0) table = table(1:n + 7)//trim(HOSTILE(1 + int(10*rnd(state))))// &
                    table(index(table(n:), NL) + n - 1:)
            case (2)
                meas = meas//', u_l = '//v
            case (3)
                call insert_bytes(table, state)
            case (4)
                table = table(1:int(len(table)*rnd(state)))
            case (5)
                meas = meas//', monte_carlo = '//itoa(1 + int(3*rnd(state)))
            end select
        case (2)
            ! a platform
            table = ''
            if (rnd(state) < 0.75_dp) then
                sus = '&suspension cables = 3, radius = 0.135, radius_prime = 0.135, '// &
                    'l = 1.0, g = 9.81'
            else
                sus = '&suspension cables = 4, support_points = 0.1, 0.1, 0, -0.1, 0.1, 0, '// &
                    '-0.1, -0.1, 0, 0.1, -0.1, 0, body_points = 0.1, 0.1, 0, -0.1, 0.1, 0, '// &
                    '-0.1, -0.1, 0, 0.1, -0.1, 0, lengths = 1.0, 1.0, 1.0, 1.0, g = 9.81'
            end if
            body = '&body mass = 2.048, inertia = 0.0243, 0.014, 0.014, cg_depth = -0.03, '// &
                'cg_offset = 0.0, 0.0'
            meas = '&measurement periods = 16.21, 16.17, cycles = 10, amplitudes = 8, 8, '// &
                'u_mass = 0.005, u_l = 0.002, u_amplitude = 2'
            select case (mut)
            case (1)
                sus = sus//', radius = '//v
            case (2)
                meas = meas//', u_l_prime = '//v
            case (3)
                body = body//', cg_depth = '//v
            case (4)
                sus = sus//', cables = '//trim(HOSTILE(1 + int(10*rnd(state))))
            case (5)
                meas = meas//', tare_i1 = 0.0093, tare_mass = '//v
            end select
            sus = sus//' /'
            body = body//' /'
        case default
            ! a record by its columns' names, or as frame numbers
            file = name//'.txt'
            sus = '&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.18, '// &
                'g = 9.80665 /'
            body = '&body mass = 3.10, inertia = 0.045, 0.0630, 0.0304, r = 0.25, '// &
                'lambda = 0.64, sway_depth = 0.30 /'//NL//"&start mode = 'raised', "// &
                'amplitude = 30.0 /'//NL//'&integration rtol = 1e-8, atol = 1e-10 /'
            meas = "&measurement record = '"//file//"', quantity = 'rate', estimate = "// &
                "'I1 amplitude', u_mass = 0.001, u_amplitude = 0.5"
            if (rnd(state) < 0.5_dp) then
                table = 'Time (s),Gyroscope z (rad/s),Note'//NL
                do i = 1, size(rec%t), FUZZ_RECORD_EVERY
                    write (row, '(f0.4,a,es16.9,a)') rec%t(i), ',', rec%v(i), ',ok'
                    table = table//trim(row)//NL
                end do
                meas = meas//", record_columns = 'time', 'gyroscope z'"
                if (mut == 5) meas = meas//', record_frame_rate = '//v
            else
                table = 'frame;W'//NL
                do i = 1, size(rec%t), FUZZ_RECORD_EVERY
                    write (row, '(i0,a,es16.9)') nint(rec%t(i)*500.0_dp), ';', rec%v(i)
                    table = table//trim(row)//NL
                end do
                if (mut == 5) then
                    meas = meas//', record_frame_rate = '//v
                else
                    meas = meas//', record_frame_rate = 500'
                end if
            end if
            select case (mut)
            case (1)
                meas = meas//", record_columns = 'frame', "//v
            case (2)
                table = scale_column(table, 2, merge(57.29577951308232_dp, 1.0e-3_dp, &
                                     rnd(state) < 0.5_dp))
            case (3)
                call insert_bytes(table, state)
            case (4)
                table = table(1:int(len(table)*rnd(state)))
            end select
        end select
        if (len(table) > 0) call write_text(dir//'/'//file, table)
        call write_text(dir//'/'//name//'.nml', head//sus//NL//body//NL//meas//' /'//NL)
    end subroutine write_measure_deck

    !> A mutated record for deck NAME: written to dir/NAME.rec (unless it is to be missing);
    !! value: the &measurement record that names it (or another file).  From the shipped
    !! record's first seconds (rec, every FUZZ_RECORD_EVERY-th sample unless dense): missing,
    !! empty, time not increasing, a token that is no finite number, too short, times or
    !! values scaled by 10^k (as text: 1e-320 ... 1e320) or one huge value, a third column
    !! (valid or not), random bytes, odd formats (commas, tabs, CR, long lines, 1 or 4
    !! columns), odd names (devices, folders, the deck itself, long names), mixed columns,
    !! and plausible records (a shift in time, degrees for radians, another rate).
    subroutine write_fuzz_record(dir, name, rec, state, value)
        character(len=*), intent(in) :: dir, name
        type(record_t), intent(in) :: rec
        integer(8), intent(inout) :: state
        character(len=:), allocatable, intent(out) :: value
        character(len=24), parameter :: tokens(16) = [character(len=24) :: 'NaN', 'Inf', &
            '-Infinity', 'nan()', '1e400', '-1e400', 'abc', '1..2', '+-1', '0x10', '1d400', &
            '.', 'e5', '1e', '"1.0"', '*']
        character(len=32), parameter :: huge_values(8) = [character(len=32) :: '1e300', &
            '-1.7976931348623157e308', '4.9e-324', '1e-320', '1e100', '1e7', '-1e15', '1e20']
        character(len=24), parameter :: thirds(9) = [character(len=24) :: '0.002', '0', &
            '-0.002', '1e300', '1e-300', '4.9e-324', 'NaN', '1e-100', '1e6']
        character(len=40), parameter :: odd_names(10) = [character(len=40) :: '/dev/zero', &
            '/dev/null', '.', '/', '', 'missing/none.dat', FUZZ_RECORD//'/', &
            ' '//FUZZ_RECORD, '/proc/self/stat', '..']
        real(dp), allocatable :: t(:), v(:), u(:)
        character(len=:), allocatable :: text, path, tsuf, vsuf, sep
        character(len=1), parameter :: NL = new_line('a')
        integer :: n, i, k, ncol
        path = dir//'/'//name//'.rec'
        value = ''''//name//'.rec'''
        n = size(rec%t)
        t = rec%t(1:n:FUZZ_RECORD_EVERY)
        v = rec%v(1:n:FUZZ_RECORD_EVERY)
        n = size(t)
        allocate (u(n))
        u = 0.002_dp
        ncol = 2
        tsuf = ''
        vsuf = ''
        sep = ' '
        select case (int(13*rnd(state)))
        case (0)
            ! missing
            return
        case (1)
            ! empty, comments only, blank lines only
            select case (int(3*rnd(state)))
            case (0)
                text = ''
            case (1)
                text = '# t (s)  W (rad/s)'//NL//'# nothing recorded'//NL
            case default
                text = NL//'   '//NL//achar(13)//NL//achar(9)//NL
            end select
        case (2)
            ! time not strictly increasing
            i = 2 + int((n - 1)*rnd(state))
            select case (int(4*rnd(state)))
            case (0)
                t(i) = t(i - 1)
            case (1)
                t(i - 1:i) = t(i:i - 1:-1)
            case (2)
                t = t(n:1:-1)
            case default
                t(i:) = t(i:) - t(n)
            end select
            text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
        case (3)
            ! a token that is no finite number, in a random row and column
            i = 1 + int(n*rnd(state))
            k = int(11*rnd(state))
            text = record_text(t(1:i - 1), v(1:i - 1), u, ncol, tsuf, vsuf, sep, .true.)
            if (k < 5) then
                text = text//trim(tokens(1 + int(size(tokens)*rnd(state))))//' '// &
                    num9(v(i))//NL
            else
                text = text//num9(t(i))//' '//trim(tokens(1 + int(size(tokens)*rnd(state))))//NL
            end if
            text = text//record_text(t(i + 1:), v(i + 1:), u, ncol, tsuf, vsuf, sep, .false.)
        case (4)
            ! too short: 0 ... 25 samples (at least 20 are needed, more than the parameters)
            k = int(26*rnd(state))
            text = record_text(t(1:k), v(1:k), u, ncol, tsuf, vsuf, sep, .true.)
        case (5)
            ! huge and tiny: times or values times 10^k, or one huge value
            k = int(641*rnd(state)) - 320
            if (k > 1 .and. k < 100) k = k + 100    ! no valid record hours long
            select case (int(3*rnd(state)))
            case (0)
                tsuf = 'e'//itoa(k)
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            case (1)
                vsuf = 'e'//itoa(k)
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            case default
                i = 1 + int(n*rnd(state))
                text = record_text(t(1:i - 1), v(1:i - 1), u, ncol, tsuf, vsuf, sep, .true.)// &
                    num9(t(i))//' '//trim(huge_values(1 + int(size(huge_values)*rnd(state))))// &
                    NL//record_text(t(i + 1:), v(i + 1:), u, ncol, tsuf, vsuf, sep, .false.)
            end select
        case (6)
            ! a third column: each sample's standard uncertainty, valid or not
            ncol = 3
            if (rnd(state) < 0.6_dp) then
                text = record_text_u(t, v, trim(thirds(1 + int(size(thirds)*rnd(state)))))
            else
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            end if
        case (7)
            ! random bytes inserted, or a record of random bytes
            text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            if (rnd(state) < 0.7_dp) then
                do k = 1, 1 + int(4*rnd(state))
                    i = 1 + int(len(text)*rnd(state))
                    text = text(1:i - 1)//random_bytes(state, 1 + int(10*rnd(state)))//text(i:)
                end do
            else
                text = random_bytes(state, int(5000*rnd(state)))
            end if
        case (8)
            ! formats: commas, tabs, CR LF, a long line, one or four columns, d exponents
            select case (int(7*rnd(state)))
            case (0)
                sep = ', '
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            case (1)
                sep = achar(9)
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            case (2)
                vsuf = achar(13)
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            case (3)
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)//repeat(' ', 4090)// &
                    '9.0 1.0'//NL
            case (4)
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)//repeat('1', &
                    1000 + int(8000*rnd(state)))//NL
            case (5)
                ! one column, or four
                k = int(2*rnd(state))
                text = ''
                do i = 1, n
                    if (k == 0) then
                        text = text//num9(t(i))//NL
                    else
                        text = text//num9(t(i))//' '//num9(v(i))//' 0.1 0.2'//NL
                    end if
                end do
            case default
                tsuf = 'd0'
                vsuf = 'D+00'
                text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
            end select
        case (9)
            ! odd names: devices, folders, the deck itself, a long name
            select case (int(3*rnd(state)))
            case (0)
                value = ''''//trim(odd_names(1 + int(size(odd_names)*rnd(state))))//''''
            case (1)
                value = ''''//name//'.nml'''
            case default
                value = ''''//repeat('r', 200 + int(100*rnd(state)))//'.dat'''
            end select
            return
        case (10)
            ! mixed columns: some rows with a third
            text = ''
            do i = 1, n
                text = text//num9(t(i))//' '//num9(v(i))
                if (rnd(state) < 0.1_dp) text = text//' 0.002'
                text = text//NL
            end do
        case (11)
            ! plausible: released before the first sample, degrees for radians, negated,
            ! every sample (dense), the first second only
            select case (int(5*rnd(state)))
            case (0)
                t = t + 0.3_dp
            case (1)
                v = v*57.29577951308232_dp
            case (2)
                v = -v
            case (3)
                t = rec%t
                v = rec%v
                deallocate (u)
                allocate (u(size(t)))
                u = 0.002_dp
            case default
                k = max(1, count(t <= 1.0_dp))
                t = t(1:k)
                v = v(1:k)
            end select
            text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
        case default
            ! the base record as it is
            text = record_text(t, v, u, ncol, tsuf, vsuf, sep, .true.)
        end select
        call write_text(path, text)
    end subroutine write_fuzz_record

    !> A record as text: one row per sample, 'time value' (and 'u' when ncol = 3), each
    !! number as text of f0.9 followed by its suffix (an exponent 'e300' scales it), the
    !! columns joined by sep; a '#' header line first when header.
    function record_text(t, v, u, ncol, tsuf, vsuf, sep, header) result(text)
        real(dp), intent(in) :: t(:), v(:), u(:)
        integer, intent(in) :: ncol
        character(len=*), intent(in) :: tsuf, vsuf, sep
        logical, intent(in) :: header
        character(len=:), allocatable :: text
        integer :: i
        text = ''
        if (header) text = '# t (s)  W (rad/s)'//new_line('a')
        do i = 1, size(t)
            text = text//num9(t(i))//tsuf//sep//num9(v(i))//vsuf
            if (ncol == 3) text = text//sep//num9(u(i))
            text = text//new_line('a')
        end do
    end function record_text

    !> A record with the text s as the third column of every row.
    function record_text_u(t, v, s) result(text)
        real(dp), intent(in) :: t(:), v(:)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: text
        integer :: i
        text = '# t (s)  W (rad/s)  u'//new_line('a')
        do i = 1, size(t)
            text = text//num9(t(i))//' '//num9(v(i))//' '//s//new_line('a')
        end do
    end function record_text_u

    !> x as the text of f0.9 ('.5' and '-.5' as they come: both are numbers).
    function num9(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=40) :: buf
        write (buf, '(f0.9)') x
        s = trim(adjustl(buf))
    end function num9

    !> `var = v` appended to group g (a later value wins in a namelist read); the group is
    !! made when absent.
    subroutine set_var(b, g, var, v)
        type(base_t), intent(inout) :: b
        integer, intent(in) :: g
        character(len=*), intent(in) :: var, v
        integer :: e
        if (len_trim(b%grp(g)) == 0) then
            b%grp(g) = '&'//trim(GROUPS(g))//' '//var//' = '//v//' /'
            return
        end if
        e = index(b%grp(g), '/', back=.true.)
        if (e == 0) e = len_trim(b%grp(g)) + 1
        b%grp(g) = b%grp(g)(1:e - 1)//', '//var//' = '//v//' /'
    end subroutine set_var

    !> A variable of group g (with subscripts now and then).
    function pick_var(g, state) result(var)
        integer, intent(in) :: g
        integer(8), intent(inout) :: state
        character(len=:), allocatable :: var
        character(len=16), parameter :: V1(3) = [character(len=16) :: 'title', 'analyses', &
            'model']
        character(len=16), parameter :: V2(5) = [character(len=16) :: 'b', 'b_prime', 'l', &
            'l_prime', 'g']
        character(len=16), parameter :: V3(8) = [character(len=16) :: 'mass', 'inertia', &
            'inertia(2)', 'r', 'lambda', 'btilde(1,:)', 'btilde(2,2)', 'sway_depth']
        character(len=16), parameter :: V4(6) = [character(len=16) :: 'mode', 'amplitude', &
            'tilt', 'theta', 'theta_dot', 'theta_dot(4)']
        character(len=25), parameter :: V5(8) = [character(len=25) :: 'tau_end', 'dtau_out', &
            'rtol', 'atol', 'error_estimate', 'method', 'sensitivities', &
            'sensitivity_error_control']
        character(len=16), parameter :: V6(2) = [character(len=16) :: 'stiffness', 'damping']
        character(len=16), parameter :: V7(3) = [character(len=16) :: 'amplitude', &
            'segments', 'rtol']
        character(len=16), parameter :: V8(8) = [character(len=16) :: 'x', 'x_min', 'x_max', &
            'nx', 'y', 'y_min', 'y_max', 'ny']
        character(len=16), parameter :: V9(1) = [character(len=16) :: 'columns']
        character(len=16), parameter :: V10(12) = [character(len=16) :: 'l_min', 'l_max', &
            'nl', 'b_min', 'b_max', 'nb', 'amplitude_max', 'n_amplitudes', 'u_mass', 'u_l', &
            'u_b', 'u_period']
        character(len=16), parameter :: V11(2) = [character(len=16) :: 'c_v', 'c_q']
        character(len=16), parameter :: V12(17) = [character(len=16) :: 'periods', &
            'periods(2)', 'amplitudes', 'amplitudes(3)', 'record', 'quantity', 'estimate', &
            'u_mass', 'u_l', 'u_l_prime', 'u_b', 'u_b_prime', 'u_g', 'u_period', &
            'u_amplitude', 'monte_carlo', 'seed']
        select case (g)
        case (GR_SCENE)
            var = trim(V1(1 + int(size(V1)*rnd(state))))
        case (GR_SUSPENSION)
            var = trim(V2(1 + int(size(V2)*rnd(state))))
        case (GR_BODY)
            var = trim(V3(1 + int(size(V3)*rnd(state))))
        case (GR_START)
            var = trim(V4(1 + int(size(V4)*rnd(state))))
        case (GR_INTEGRATION)
            var = trim(V5(1 + int(size(V5)*rnd(state))))
        case (GR_CABLES)
            var = trim(V6(1 + int(size(V6)*rnd(state))))
        case (GR_FLOQUET)
            var = trim(V7(1 + int(size(V7)*rnd(state))))
        case (GR_CHART)
            var = trim(V8(1 + int(size(V8)*rnd(state))))
        case (GR_OUTPUT)
            var = trim(V9(1))
        case (GR_DESIGN)
            var = trim(V10(1 + int(size(V10)*rnd(state))))
        case (GR_DAMPING)
            var = trim(V11(1 + int(size(V11)*rnd(state))))
        case default
            var = trim(V12(1 + int(size(V12)*rnd(state))))
        end select
    end function pick_var

    !> A value for var: hostile (kind 0), random (1) or nearby (2, 3); never a valid value
    !! that asks for much work (long runs, big charts and designs, many Monte Carlo samples).
    function pick_value(var, kind, state) result(v)
        character(len=*), intent(in) :: var
        integer, intent(in) :: kind
        integer(8), intent(inout) :: state
        character(len=:), allocatable :: v
        character(len=24), parameter :: hostile(30) = [character(len=24) :: 'NaN', 'Inf', &
            '-Inf', '+Infinity', 'nan()', '1e400', '-1e400', '1e-400', '0', '-0.0', &
            '1.7976931348623157e308', '4.9e-324', '-1', '1e300', '1e-300', '2147483648', &
            '''abc''', 'abc', '.true.', '3*', '1,2,3,4,5,6,7,8,9,10', '1d0', '', '(1.0,2.0)', &
            '1e99', '-1e-99', '.5', '1e6', '&', '/']
        ! the analyses; those from NWP_FIRST on ask for work_precision (chosen rarely)
        integer, parameter :: NWP_FIRST = 18
        character(len=40), parameter :: analyses(20) = [character(len=40) :: '''simulate''', &
            '''floquet''', '''chart''', '''simulate floquet''', '''floquet chart simulate''', &
            '''chart simulate''', '''garbage''', '''''', '''simulate simulate''', &
            '''Floquet  SIMULATE''', '''design''', '''identify''', '''design floquet''', &
            '''identify simulate''', '''chart design''', '''Identify''', &
            '''simulate design identify''', '''work_precision''', '''work_precision floquet''', &
            '''identify work_precision''']
        character(len=16), parameter :: models(4) = [character(len=16) :: '''kane''', &
            '''elastic''', '''Elastic''', '''rigid''']
        character(len=16), parameter :: modes(4) = [character(len=16) :: '''raised''', &
            '''angles''', '''ANGLES''', '''dropped''']
        character(len=16), parameter :: methods(6) = [character(len=16) :: '''auto''', &
            '''lsoda''', '''radau''', '''RADAU''', '''rk4''', '''''']
        character(len=16), parameter :: sens_ways(5) = [character(len=16) :: '''forward''', &
            '''differences''', '''FORWARD''', '''adjoint''', '''''']
        character(len=16), parameter :: axes(8) = [character(len=16) :: '''l''', '''b''', &
            '''amplitude''', '''r''', '''lambda''', '''inertia_ratio''', '''theta''', '''''']
        character(len=8), parameter :: counts_n(8) = [character(len=8) :: '0', '1', '2', '3', &
            '-1', '1001', '65', '2.5']
        ! design grids of at most 3 x 2 candidates at 2 amplitudes when valid
        character(len=12), parameter :: counts_nl(8) = [character(len=12) :: '-1', '0', '1', &
            '2', '3', '1001', '2.5', '2147483648']
        character(len=12), parameter :: counts_nb(6) = [character(len=12) :: '-1', '0', '1', &
            '2', '1001', '2.5']
        character(len=12), parameter :: counts_na(6) = [character(len=12) :: '-1', '0', '1', &
            '2', '101', '2.5']
        character(len=12), parameter :: counts_mc(8) = [character(len=12) :: '0', '1', '2', &
            '3', '-1', '1000001', '2.5', '2147483648']
        character(len=12), parameter :: seeds(8) = [character(len=12) :: '1', '0', '-1', '7', &
            '2147483647', '-2147483648', '2147483648', '1e3']
        character(len=24), parameter :: records(10) = [character(len=24) :: &
            ''''//FUZZ_RECORD//'''', '''missing.dat''', '''''', '''/dev/null''', &
            '''/dev/zero''', '''.''', '''/''', ''' '//FUZZ_RECORD//'''', '''REC_BASE.DAT''', &
            ''''//FUZZ_RECORD//'/''']
        character(len=16), parameter :: quantities(7) = [character(len=16) :: '''angle''', &
            '''rate''', '''RATE''', '''Angle''', '''speed''', '''''', '''angle rate''']
        character(len=40), parameter :: estimates(10) = [character(len=40) :: '''I1''', &
            '''I1 c_v''', '''I1 c_v c_q amplitude t0''', '''I1 t0''', '''c_v''', '''I1 I1''', &
            '''i1 C_Q''', '''I1 mass''', '''''', '''I1 amplitude''']
        integer :: i, k
        select case (var)
        case ('analyses')
            i = 1 + int(size(analyses)*rnd(state))
            ! work_precision times each point for 0.05 s: rarely
            if (i >= NWP_FIRST) then
                if (rnd(state) > 0.2_dp) i = 1 + int((NWP_FIRST - 1)*rnd(state))
            end if
            v = trim(analyses(i))
            return
        case ('model')
            v = trim(models(1 + int(size(models)*rnd(state))))
            return
        case ('mode')
            v = trim(modes(1 + int(size(modes)*rnd(state))))
            return
        case ('method')
            v = trim(methods(1 + int(size(methods)*rnd(state))))
            return
        case ('sensitivities')
            v = trim(sens_ways(1 + int(size(sens_ways)*rnd(state))))
            return
        case ('x', 'y')
            v = trim(axes(1 + int(size(axes)*rnd(state))))
            return
        case ('nx', 'ny', 'segments')
            v = trim(counts_n(1 + int(size(counts_n)*rnd(state))))
            return
        case ('nl')
            v = trim(counts_nl(1 + int(size(counts_nl)*rnd(state))))
            return
        case ('nb')
            v = trim(counts_nb(1 + int(size(counts_nb)*rnd(state))))
            return
        case ('n_amplitudes')
            v = trim(counts_na(1 + int(size(counts_na)*rnd(state))))
            return
        case ('monte_carlo')
            v = trim(counts_mc(1 + int(size(counts_mc)*rnd(state))))
            return
        case ('seed')
            v = trim(seeds(1 + int(size(seeds)*rnd(state))))
            return
        case ('record')
            v = trim(records(1 + int(size(records)*rnd(state))))
            if (kind == 0) v = trim(hostile(1 + int(size(hostile)*rnd(state))))
            return
        case ('quantity')
            v = trim(quantities(1 + int(size(quantities)*rnd(state))))
            return
        case ('estimate')
            v = trim(estimates(1 + int(size(estimates)*rnd(state))))
            return
        case ('columns')
            v = random_columns(state)
            if (kind == 0) v = trim(hostile(1 + int(size(hostile)*rnd(state))))
            return
        case ('title')
            v = '''fuzz '//random_bytes_printable(state, int(40*rnd(state)))//''''
            return
        case ('error_estimate', 'sensitivity_error_control')
            v = trim(merge('.true. ', '.false.', rnd(state) < 0.5_dp))
            if (kind == 0) v = trim(hostile(1 + int(size(hostile)*rnd(state))))
            return
        case ('periods', 'amplitudes')
            ! a list now and then
            if (kind >= 2) then
                if (rnd(state) < 0.4_dp) then
                    v = nearby(var, state)
                    do k = 1, int(4*rnd(state))
                        v = v//', '//nearby(var, state)
                    end do
                    return
                end if
            end if
        end select
        select case (kind)
        case (0)
            v = trim(hostile(1 + int(size(hostile)*rnd(state))))
        case (1)
            ! no valid value that asks for a long run
            if (var == 'tau_end') then
                v = random_real(state, -1)
            else
                v = random_real(state, 320)
            end if
        case default
            v = nearby(var, state)
        end select
    end function pick_value

    !> A value near the usual ones of var, valid or just outside its range.
    function nearby(var, state) result(v)
        character(len=*), intent(in) :: var
        integer(8), intent(inout) :: state
        character(len=:), allocatable :: v
        real(dp) :: x, typical
        character(len=40) :: buf
        select case (var)
        case ('tau_end')
            typical = 1.0_dp
        case ('dtau_out')
            typical = 0.05_dp
        case ('rtol', 'atol')
            typical = 1.0e-8_dp
        case ('amplitude', 'amplitude_max', 'amplitudes', 'amplitudes(3)')
            typical = 30.0_dp
        case ('stiffness')
            typical = 1.0e5_dp
        case ('damping', 'u_amplitude')
            typical = 0.5_dp
        case ('tilt', 'lambda', 'theta', 'theta_dot', 'theta_dot(4)', 'x_min', 'x_max', &
              'y_min', 'y_max', 'l_min', 'b_min', 'b_max')
            typical = 0.5_dp
        case ('inertia', 'inertia(2)')
            typical = 0.15_dp
        case ('c_v', 'c_q', 'u_mass', 'u_l', 'u_l_prime', 'u_b', 'u_b_prime', 'u_g')
            typical = 1.0e-3_dp
        case ('u_period')
            typical = 1.0e-4_dp
        case default
            typical = 1.5_dp
        end select
        x = typical*2.0_dp**(8.0_dp*rnd(state) - 4.0_dp)
        if (rnd(state) < 0.1_dp) x = -x
        write (buf, '(es12.5)') x
        v = trim(adjustl(buf))
    end function nearby

    !> A value for &output columns: names of OUTPUT_COLUMNS in any order and case, now and
    !! then one twice or unknown, or none.
    function random_columns(state) result(v)
        integer(8), intent(inout) :: state
        character(len=:), allocatable :: v
        character(len=20) :: names(17)
        character(len=len(OUTPUT_COLUMNS)) :: all
        integer :: k, j
        all = OUTPUT_COLUMNS
        read (all, *) names
        v = ''
        do k = 1, 1 + int(6*rnd(state))
            j = 1 + int(size(names)*rnd(state))
            if (rnd(state) < 0.1_dp) then
                v = v//' '//upper(trim(names(j)))
            else
                v = v//' '//trim(names(j))
            end if
        end do
        select case (int(10*rnd(state)))
        case (0)
            v = v//' tau'
        case (1)
            v = v//' theta6'
        case (2)
            v = ' '
        case (3)
            v = ' '//OUTPUT_COLUMNS
        end select
        v = ''''//v(2:)//''''
    end function random_columns


    !> Group lines, one per line, the absent ones left out.
    function assemble(grp) result(text)
        character(len=*), intent(in) :: grp(:)
        character(len=:), allocatable :: text
        integer :: i
        text = ''
        do i = 1, size(grp)
            if (len_trim(grp(i)) > 0) text = text//trim(grp(i))//new_line('a')
        end do
    end function assemble

    !> Uniform in [0, 1) from a 64-bit linear congruential generator (fixed seeds: the same
    !! decks on every machine).
    real(dp) function rnd(state)
        integer(8), intent(inout) :: state
        integer(8), parameter :: a = 6364136223846793005_8, c = 1442695040888963407_8
        state = a*state + c     ! wraps modulo 2**64 (two's complement)
        rnd = real(ishft(state, -11), dp)*2.0_dp**(-53)
    end function rnd

    function random_bytes(state, n) result(s)
        integer(8), intent(inout) :: state
        integer, intent(in) :: n
        character(len=n) :: s
        integer :: i
        do i = 1, n
            s(i:i) = achar(int(256*rnd(state)))
        end do
    end function random_bytes

    !> Printable characters other than quotes.
    function random_bytes_printable(state, n) result(s)
        integer(8), intent(inout) :: state
        integer, intent(in) :: n
        character(len=n) :: s
        integer :: i
        do i = 1, n
            s(i:i) = achar(32 + int(95*rnd(state)))
            if (s(i:i) == '''') s(i:i) = '"'
        end do
    end function random_bytes_printable

    !> A real of random sign and magnitude 1e-320 ... 1e320 (as text), its decimal exponent
    !! at most emax.
    function random_real(state, emax) result(s)
        integer(8), intent(inout) :: state
        integer, intent(in) :: emax
        character(len=:), allocatable :: s
        character(len=40) :: buf
        real(dp) :: m
        integer :: e
        m = 1.0_dp + 9.0_dp*rnd(state)
        e = int(640*rnd(state)) - 320
        if (rnd(state) < 0.5_dp) e = int(8*rnd(state)) - 4
        e = min(e, emax)
        write (buf, '(f0.6,a,i0)') m, 'e', e
        s = trim(buf)
        if (rnd(state) < 0.3_dp) s = '-'//s
    end function random_real

    !> A run that ended by a signal or a timeout (exit status beyond 5) or printed a run-time
    !! error, a backtrace or gfortran's STOP line.
    logical function abnormal(ex, errfile)
        integer, intent(in) :: ex
        character(len=*), intent(in) :: errfile     !! its standard error
        abnormal = ex > 5 .or. ex < 0
        if (file_has(errfile, 'untime error')) abnormal = .true.
        if (file_has(errfile, 'Backtrace')) abnormal = .true.
        if (file_has(errfile, 'STOP')) abnormal = .true.
    end function abnormal

    !> Whether a line of a file starts with prefix and contains s.
    logical function line_with(path, prefix, s)
        character(len=*), intent(in) :: path, prefix, s
        integer :: u, ios
        character(len=8192) :: line
        line_with = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, prefix) == 1 .and. index(line, s) > 0) then
                line_with = .true.
                exit
            end if
        end do
        close (u)
    end function line_with

    !> KIND of the error line 'bifilar: error (KIND): ...' that contains s ('' when none).
    function error_kind(path, s) result(kind)
        character(len=*), intent(in) :: path, s
        character(len=:), allocatable :: kind
        integer :: u, ios, e
        character(len=8192) :: line
        kind = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, s) == 0 .or. index(line, 'bifilar: note: ') == 1 .or. &
                index(line, 'bifilar: warning: ') == 1) cycle
            kind = '?'
            e = index(line, '): ')
            if (index(line, 'bifilar: error (') == 1 .and. e > 17) kind = line(17:e - 1)
            exit
        end do
        close (u)
    end function error_kind

end module test_fuzz
