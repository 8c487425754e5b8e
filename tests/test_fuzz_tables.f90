!> The in-process fuzz: records, tables of releases (periods), tables of hangs
!! and sweep checkpoints, mutated in their values and units (times in ms, from the epoch,
!! with gaps; values in degrees, deg/s, with their sign flipped; random bytes, a BOM,
!! tokens that are no number, rows cut or doubled) and read through the library's own
!! readers and checks (read_record and check_record_times, read_releases and
!! check_timings, read_hangs, checkpoint_read), not the executable: cheap, so they are many.  Every case
!! asserts: a refusal is one line naming the file; what is taken is finite and within
!! its range; the unit mistakes the audit named (ms, a 1000 s gap, deg/s read as rad/s,
!! periods in ms) are refused before any computing; a checkpoint gives back only values
!! bit for bit as written.  The cases are the same in every build.
module test_fuzz_tables
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use status, only: status_t, STATUS_OK
    use testing, only: tester_t, write_text, fresh_dir
    use text, only: itoa
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, start_of, read_record, deck_inputs
    use rig, only: rig_t
    use records, only: record_t, MIN_SAMPLES
    use measurement, only: measurement_t
    use measurement_read, only: read_releases, read_hangs
    use work_estimate, only: check_record_times, check_timings, periods_runs
    use checkpoint, only: checkpoint_write, checkpoint_read
    use tensor, only: tensor_ready
    use unused_arg, only: unused
    implicit none
    private

    public :: run_fuzz_table_tests, scale_column, insert_bytes, file_text

    character(len=*), parameter :: SCRATCH = 'build/test_fuzz_tables'
    !> Cases of each kind (records, tables of releases, tables of hangs, checkpoints).
    integer, parameter :: N_RECORDS = 400, N_TRIALS = 300, N_HANGS = 300, N_CKPT = 300
    integer(8), parameter :: SEED = 20261125_8
    character(len=1), parameter :: NL = achar(10)
    !> Tokens that are no finite number.
    character(len=8), parameter :: TOKENS(10) = [character(len=8) :: 'NaN', 'Inf', '1e400', &
        'abc', '1..2', '+-1', '0x10', '*', '-', ',,']

contains

    subroutine run_fuzz_table_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! (not run: the cases are in process)
        integer :: ncase
        integer(8) :: state
        call unused(exe)
        if (.not. t%want('fuzz_tables: records, periods, hangs and checkpoints mutated, '// &
                         'read in process')) return
        call fresh_dir(SCRATCH)
        state = SEED
        ncase = 0
        call fuzz_records(t, state, ncase)
        call fuzz_trials(t, state, ncase)
        call fuzz_hangs(t, state, ncase)
        call fuzz_checkpoints(t, state, ncase)
        call estimate_many_periods(t)
        write (*, '(a,i0,a)') '   fuzz_tables: ', ncase, ' cases in process (records, '// &
            'tables of releases, tables of hangs, checkpoints)'
        call t%check('fuzz_tables: at least 1200 cases', ncase >= 1200)
        call execute_command_line('rm -rf '//SCRATCH)
    end subroutine run_fuzz_table_tests

    ! ---------------------------------------------------------------------------------------
    !> Records: the shipped gyro record (input/identify_record.nml, rad/s) cut to its first
    !! 500 samples, mutated, read by read_record and weighed by check_record_times.
    subroutine fuzz_records(t, state, ncase)
        type(tester_t), intent(inout) :: t
        integer(8), intent(inout) :: state
        integer, intent(inout) :: ncase
        type(deck_t) :: d0, d
        type(record_t) :: full, rec
        type(rig_t) :: rg
        type(status_t) :: st, sc
        real(dp), allocatable :: tt(:), vv(:)
        character(len=:), allocatable :: text, path, what, msg
        integer :: k, n, i, kind, nbad(4), counts(3)
        logical :: must_refuse, same_as, negated
        real(dp) :: scale
        character(len=*), parameter :: WHAT_BAD(4) = [character(len=48) :: &
            'refusal not one line naming the record', 'taken value not finite or in range', &
            'unit mistake not refused', 'valid mutation misread']
        character(len=120) :: first_bad(4)
        call read_deck('input/identify_record.nml', d0, st)
        call t%check('fuzz_tables: input/identify_record.nml read', st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        call read_record(d0, full, st)
        call t%check('fuzz_tables: its record read', st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        n = min(500, size(full%t))
        rg = rig_of(d0)
        nbad = 0
        counts = 0
        first_bad = ''
        path = SCRATCH//'/rec.dat'
        do k = 1, N_RECORDS
            d = d0
            d%measurement%record = 'rec.dat'
            d%measurement%record_path = path
            tt = full%t(1:n)
            vv = full%v(1:n)
            must_refuse = .false.
            same_as = .false.
            negated = .false.
            scale = 1.0_dp
            kind = int(12*rnd(state))
            what = 'kind '//itoa(kind)
            select case (kind)
            case (0)
                ! times in ms
                tt = 1000.0_dp*tt
                must_refuse = .true.
                what = 'times in ms'
            case (1)
                ! times from the epoch (s): a valid record released long before
                tt = tt + 1.7e9_dp + real(int(1.0e6_dp*rnd(state)), dp)
                what = 'times from the epoch'
            case (2)
                ! a gap of 100 s to 1e5 s
                i = 2 + int((n - 2)*rnd(state))
                tt(i:) = tt(i:) + 10.0_dp**(2 + int(4*rnd(state)))
                must_refuse = .true.
                what = 'a gap'
            case (3)
                ! the sign flipped
                vv = -vv
                negated = .true.
                what = 'sign flipped'
            case (4)
                ! deg/s read as rad/s
                vv = vv*57.29577951308232_dp
                must_refuse = .true.
                what = 'deg/s as rad/s'
            case (5)
                ! deg/s, said so
                vv = vv*57.29577951308232_dp
                d%measurement%record_units = 'deg/s'
                same_as = .true.
                scale = 1.0_dp
                what = 'deg/s said'
            case (6)
                ! a UTF-8 BOM, CR LF, tabs
                same_as = .true.
                what = 'BOM, CR LF'
            case (7)
                ! a token that is no number
                what = 'a token'
            case (8)
                ! random bytes
                what = 'random bytes'
            case (9)
                ! rows cut (too short) or doubled (time not increasing)
                if (rnd(state) < 0.5_dp) then
                    i = int(2*MIN_SAMPLES*rnd(state))
                    tt = tt(1:i)
                    vv = vv(1:i)
                    what = 'cut'
                else
                    i = 2 + int((n - 2)*rnd(state))
                    tt(i) = tt(i - 1)
                    must_refuse = .true.
                    what = 'a row doubled'
                end if
            case (10)
                ! values scaled by a power of ten
                scale = 10.0_dp**(int(13*rnd(state)) - 6)
                vv = vv*scale
                what = 'values scaled'
            case default
                ! as it is
                same_as = .true.
                what = 'as it is'
            end select
            text = rows(tt, vv)
            select case (kind)
            case (6)
                text = char(239)//char(187)//char(191)//'# t W'//achar(13)//NL// &
                    crlf_tabs(text)
            case (7)
                i = 1 + int((len(text) - 1)*rnd(state))
                text = text(1:i)//' '//trim(TOKENS(1 + int(size(TOKENS)*rnd(state))))// &
                    text(i + 1:)
            case (8)
                do i = 1, 1 + int(3*rnd(state))
                    call insert_bytes(text, state)
                end do
            end select
            call write_text(path, text)
            call read_record(d, rec, st)
            ncase = ncase + 1
            if (st%code /= STATUS_OK) then
                counts(1) = counts(1) + 1
                if (.not. one_line_naming(st%msg, 'rec.dat')) call bad(1, what//': '//st%msg)
                if (same_as .or. negated) call bad(4, what//': '//st%msg)
                cycle
            end if
            if (.not. sane_record(rec)) call bad(2, what)
            if (same_as) then
                if (.not. close_to(rec%v, full%v(1:n))) call bad(4, what)
            else if (negated) then
                if (.not. close_to(rec%v, -full%v(1:n))) call bad(4, what)
            end if
            call check_record_times(d%body, d%measurement, d%start, rg, rec, 'rec.dat', sc)
            if (sc%code /= STATUS_OK) then
                counts(2) = counts(2) + 1
                msg = sc%msg
                if (.not. one_line_naming(msg, 'rec.dat')) call bad(1, what//': '//msg)
                if (same_as .or. negated) call bad(4, what//': '//msg)
            else
                counts(3) = counts(3) + 1
                if (must_refuse) call bad(3, what)
            end if
        end do
        write (*, '(a,4(i0,a))') '   fuzz_tables: ', N_RECORDS, ' records: ', counts(1), &
            ' refused by the reader, ', counts(2), ' by the work check, ', &
            counts(3), ' taken'
        do i = 1, size(nbad)
            call t%check('fuzz_tables: records: '//trim(WHAT_BAD(i))//': '//itoa(nbad(i))// &
                         ' '//trim(first_bad(i)), nbad(i) == 0)
        end do
        call t%check('fuzz_tables: records: some refused, some taken', &
                     counts(1) > 0 .and. counts(2) > 0 .and. counts(3) > 0)

    contains

        subroutine bad(j, s)
            integer, intent(in) :: j
            character(len=*), intent(in) :: s
            nbad(j) = nbad(j) + 1
            if (len_trim(first_bad(j)) == 0) first_bad(j) = '(first: '//s(1:min(len(s), 100))//')'
        end subroutine bad

    end subroutine fuzz_records

    ! ---------------------------------------------------------------------------------------
    !> Tables of releases: input/identify_trials.csv mutated, read by read_releases (the
    !! measurement's model) and each release's periods weighed by check_timings.
    subroutine fuzz_trials(t, state, ncase)
        type(tester_t), intent(inout) :: t
        integer(8), intent(inout) :: state
        integer, intent(inout) :: ncase
        type(deck_t) :: d0, d
        type(measurement_t) :: ts
        type(rig_t) :: rg
        type(status_t) :: st, sc
        character(len=:), allocatable :: base, text, path, what
        integer :: k, i, j, kind, nbad(3), counts(3)
        logical :: must_refuse, valid
        character(len=120) :: first_bad(3)
        character(len=*), parameter :: WHAT_BAD(3) = [character(len=48) :: &
            'refusal not one line naming the table', 'taken value not finite or in range', &
            'unit mistake not refused or valid one refused']
        call read_deck('input/identify_trials.nml', d0, st)
        call t%check('fuzz_tables: input/identify_trials.nml read', st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        base = file_text('input/identify_trials.csv')
        rg = rig_of(d0)
        path = SCRATCH//'/trials.csv'
        nbad = 0
        counts = 0
        first_bad = ''
        do k = 1, N_TRIALS
            d = d0
            d%measurement%trials = 'trials.csv'
            d%measurement%trials_path = path
            must_refuse = .false.
            valid = .false.
            kind = int(9*rnd(state))
            what = 'kind '//itoa(kind)
            select case (kind)
            case (0)
                text = scale_column(base, 4, 1000.0_dp)
                must_refuse = .true.
                what = 'periods in ms'
            case (1)
                text = scale_column(base, 4, -1.0_dp)
                what = 'periods negated'
            case (2)
                text = scale_column(base, 6, 10.0_dp**(int(5*rnd(state)) - 2))
                what = 'amplitudes scaled'
            case (3)
                text = scale_column(base, 5, real(int(3*rnd(state)) - 1, dp))
                what = 'cycles -1, 0 or 1'
            case default
                call table_mutation(base, kind - 3, state, text, valid, what)
            end select
            call write_text(path, text)
            call read_releases(d%measurement, rig_of(d), start_of(d), d%suspension%cables, &
                               deck_inputs(d, .true.), ts, st)
            ncase = ncase + 1
            if (st%code /= STATUS_OK) then
                counts(1) = counts(1) + 1
                if (.not. one_line_naming(st%msg, 'trials.csv')) call bad(1, what//': '//st%msg)
                if (valid) call bad(3, what//': '//st%msg)
                cycle
            end if
            sc%code = STATUS_OK
            do i = 1, size(ts%releases)
                associate (per => ts%periods_of(i), cyc => ts%cycles_of(i), &
                           amps => ts%amplitudes_of(i), g => ts%releases(i)%rig)
                    do j = 1, size(per)
                        if (.not. (ieee_is_finite(per(j)) .and. per(j) > 0.0_dp .and. &
                                   cyc(j) > 0.0_dp .and. ieee_is_finite(cyc(j)) .and. &
                                   amps(j) >= 0.0_dp .and. amps(j) < 180.0_dp)) &
                            call bad(2, what)
                    end do
                    if (.not. all(ieee_is_finite([g%l, g%l_prime, g%b, g%b_prime, g%mass]) .and. &
                                  [g%l, g%l_prime, g%b, g%b_prime, g%mass] > 0.0_dp)) &
                        call bad(2, what)
                    if (sc%code == STATUS_OK) call check_timings(d%body, rg, per, amps, &
                        size(ts%releases) == 1, sc)
                end associate
            end do
            if (sc%code /= STATUS_OK) then
                counts(2) = counts(2) + 1
                if (.not. one_line_naming(sc%msg, 'periods(')) call bad(1, what//': '//sc%msg)
                if (valid) call bad(3, what//': '//sc%msg)
            else
                counts(3) = counts(3) + 1
                if (must_refuse) call bad(3, what)
            end if
        end do
        write (*, '(a,4(i0,a))') '   fuzz_tables: ', N_TRIALS, ' tables of releases: ', &
            counts(1), ' refused by the reader, ', counts(2), ' by the work check, ', &
            counts(3), ' taken'
        do i = 1, size(nbad)
            call t%check('fuzz_tables: releases: '//trim(WHAT_BAD(i))//': '//itoa(nbad(i))// &
                         ' '//trim(first_bad(i)), nbad(i) == 0)
        end do
        call t%check('fuzz_tables: releases: some refused, some taken', &
                     counts(1) > 0 .and. counts(2) > 0 .and. counts(3) > 0)

    contains

        subroutine bad(j, s)
            integer, intent(in) :: j
            character(len=*), intent(in) :: s
            nbad(j) = nbad(j) + 1
            if (len_trim(first_bad(j)) == 0) first_bad(j) = '(first: '//s(1:min(len(s), 100))//')'
        end subroutine bad

    end subroutine fuzz_trials

    ! ---------------------------------------------------------------------------------------
    !> Tables of hangs: input/tensor_example_hangs.csv mutated, read by read_hangs.
    subroutine fuzz_hangs(t, state, ncase)
        type(tester_t), intent(inout) :: t
        integer(8), intent(inout) :: state
        integer, intent(inout) :: ncase
        type(deck_t) :: d0, d
        type(measurement_t) :: set
        type(status_t) :: st
        character(len=:), allocatable :: base, text, path, what
        integer :: k, i, kind, nbad(3), counts(3)
        logical :: valid, must_refuse
        character(len=120) :: first_bad(3)
        character(len=*), parameter :: WHAT_BAD(3) = [character(len=48) :: &
            'refusal not one line naming the table', 'taken value not finite or in range', &
            'unit mistake not refused or valid one refused']
        call read_deck('input/tensor_example.nml', d0, st)
        call t%check('fuzz_tables: input/tensor_example.nml read', st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        base = file_text('input/tensor_example_hangs.csv')
        path = SCRATCH//'/hangs.csv'
        nbad = 0
        counts = 0
        first_bad = ''
        do k = 1, N_HANGS
            d = d0
            d%tensor%hangs = 'hangs.csv'
            d%tensor%hangs_path = path
            valid = .false.
            must_refuse = .false.
            kind = int(10*rnd(state))
            what = 'kind '//itoa(kind)
            select case (kind)
            case (0)
                text = scale_column(base, 8, 1000.0_dp)
                must_refuse = .true.
                what = 'periods in ms'
            case (1)
                text = scale_column(base, 8, -1.0_dp)
                what = 'periods negated'
            case (2)
                ! up and along both flipped: the same hang
                text = scale_column(scale_column(base, 2 + int(3*rnd(state)), -1.0_dp), &
                                    5 + int(3*rnd(state)), -1.0_dp)
                valid = .true.
                what = 'directions flipped'
            case (3)
                text = scale_column(base, 10, 10.0_dp**(int(5*rnd(state)) - 2))
                what = 'amplitudes scaled'
            case (4)
                text = scale_column(base, 9, real(int(3*rnd(state)) - 1, dp))
                what = 'cycles -1, 0 or 1'
            case default
                call table_mutation(base, kind - 4, state, text, valid, what)
            end select
            call write_text(path, text)
            call read_hangs(d%tensor, d%suspension, d%body, set, st)
            ncase = ncase + 1
            if (st%code /= STATUS_OK) then
                counts(1) = counts(1) + 1
                if (.not. one_line_naming(st%msg, 'hangs.csv')) call bad(1, what//': '//st%msg)
                if (valid) call bad(3, what//': '//st%msg)
                cycle
            end if
            ! the analysis's preconditions (each hang's rig, the periods against it)
            call tensor_ready(d, st)
            if (st%code /= STATUS_OK) then
                counts(2) = counts(2) + 1
                if (.not. one_line_naming(st%msg, 'hangs.csv')) call bad(1, what//': '//st%msg)
                if (valid) call bad(3, what//': '//st%msg)
            else
                counts(3) = counts(3) + 1
                if (must_refuse) call bad(3, what)
            end if
            do i = 1, size(set%obs)
                if (.not. (ieee_is_finite(set%obs(i)%period) .and. set%obs(i)%period > 0.0_dp &
                           .and. ieee_is_finite(set%obs(i)%cycles) .and. &
                           set%obs(i)%cycles > 0.0_dp .and. set%obs(i)%amplitude >= 0.0_dp &
                           .and. set%obs(i)%amplitude < 180.0_dp)) call bad(2, what)
            end do
            do i = 1, size(set%releases)
                associate (h => set%releases(i)%hang)
                    if (.not. (abs(norm2(h%up) - 1.0_dp) < 1.0e-9_dp .and. &
                               abs(norm2(h%along) - 1.0_dp) < 1.0e-9_dp .and. &
                               abs(dot_product(h%up, h%along)) < 1.0e-6_dp)) &
                        call bad(2, what//' hang '//itoa(i))
                end associate
            end do
        end do
        write (*, '(a,4(i0,a))') '   fuzz_tables: ', N_HANGS, ' tables of hangs: ', &
            counts(1), ' refused by the reader, ', counts(2), ' by the analysis''s checks, ', &
            counts(3), ' taken'
        do i = 1, size(nbad)
            call t%check('fuzz_tables: hangs: '//trim(WHAT_BAD(i))//': '//itoa(nbad(i))// &
                         ' '//trim(first_bad(i)), nbad(i) == 0)
        end do
        call t%check('fuzz_tables: hangs: some refused, some taken', all(counts > 0))

    contains

        subroutine bad(j, s)
            integer, intent(in) :: j
            character(len=*), intent(in) :: s
            nbad(j) = nbad(j) + 1
            if (len_trim(first_bad(j)) == 0) first_bad(j) = '(first: '//s(1:min(len(s), 100))//')'
        end subroutine bad

    end subroutine fuzz_hangs

    ! ---------------------------------------------------------------------------------------
    !> Checkpoints: one written by checkpoint_write (values that include NaN and Inf bit
    !! patterns are not written: a sweep's values are finite), then a hex digit changed, a
    !! byte inserted, the file cut, a line doubled or a NaN pattern put in a record, and
    !! read by checkpoint_read: every point taken holds the very bits written.
    subroutine fuzz_checkpoints(t, state, ncase)
        type(tester_t), intent(inout) :: t
        integer(8), intent(inout) :: state
        integer, intent(inout) :: ncase
        integer, parameter :: NV = 3, NP = 24
        real(dp) :: vals(NV, NP), got(NV, NP)
        logical :: done0(NP), got_done(NP)
        integer(int64), parameter :: DECK_CRC = 123456789_int64, EXE_CRC = 987654321_int64
        type(status_t) :: st
        character(len=:), allocatable :: path, base, text, note
        integer :: k, i, j, ndone, nbad, kind, bad_bits, bad_count, counts(3)
        path = SCRATCH//'/sweep.partial'
        bad_bits = 0
        bad_count = 0
        counts = 0
        do k = 1, N_CKPT
            do j = 1, NP
                do i = 1, NV
                    vals(i, j) = (rnd(state) - 0.5_dp)*10.0_dp**(int(20*rnd(state)) - 10)
                end do
                done0(j) = rnd(state) < 0.7_dp
            end do
            call checkpoint_write(path, 'chart', DECK_CRC, EXE_CRC, vals, done0, st)
            if (st%code /= STATUS_OK) then
                bad_count = bad_count + 1
                cycle
            end if
            base = file_text(path)
            text = base
            kind = int(6*rnd(state))
            select case (kind)
            case (0)
                ! one hex digit changed in a record (3FF0... -> 4FF0...)
                i = len(base) - int((len(base)/2)*rnd(state))
                i = max(1, min(i, len(text) - 5))
                if (index('0123456789ABCDEF', text(i:i)) > 0) then
                    text(i:i) = merge('4', '3', text(i:i) /= '4')
                end if
            case (1)
                call insert_bytes(text, state)
            case (2)
                text = base(1:int(len(base)*rnd(state)))
            case (3)
                ! a NaN or Inf pattern in place of a value (its CRC left as it was)
                i = index(base, NL//'1 ')
                if (i == 0) i = index(base, 'done ')
                j = index(base(i + 1:), ' ') + i
                if (j + 16 <= len(text)) text(j + 1:j + 16) = merge('7FF8000000000000', &
                    '7FF0000000000000', rnd(state) < 0.5_dp)
            case (4)
                ! a record line doubled
                i = index(base, 'done ')
                i = i + index(base(i:), NL)
                j = i + index(base(i:), NL) - 1
                text = base(1:j)//base(i:j)//base(j + 1:)
            case default
                ! as written
            end select
            call write_text(path, text)
            got = 0.0_dp
            got_done = .false.
            call checkpoint_read(path, 'chart', DECK_CRC, EXE_CRC, got, got_done, ndone, nbad, &
                                 note)
            ncase = ncase + 1
            if (index(note, NL) > 0) bad_count = bad_count + 1
            if (ndone == 0) then
                counts(1) = counts(1) + 1
            else if (nbad > 0) then
                counts(2) = counts(2) + 1
            else
                counts(3) = counts(3) + 1
            end if
            ! every point taken: written as done, with the same bits
            do j = 1, NP
                if (.not. got_done(j)) cycle
                if (.not. done0(j)) bad_bits = bad_bits + 1
                do i = 1, NV
                    if (transfer(got(i, j), 0_int64) /= transfer(vals(i, j), 0_int64)) &
                        bad_bits = bad_bits + 1
                end do
            end do
            if (count(got_done) /= ndone) bad_count = bad_count + 1
            if (kind == 5 .and. (ndone /= count(done0) .or. nbad /= 0)) &
                bad_count = bad_count + 1
        end do
        write (*, '(a,4(i0,a))') '   fuzz_tables: ', N_CKPT, ' checkpoints: ', counts(1), &
            ' ignored, ', counts(2), ' taken in part, ', counts(3), ' taken whole'
        call t%check('fuzz_tables: checkpoints: every value taken as written: '// &
                     itoa(bad_bits)//' wrong', bad_bits == 0)
        call t%check('fuzz_tables: checkpoints: counts, notes on one line, a whole file '// &
                     'taken whole: '//itoa(bad_count)//' wrong', bad_count == 0)
        call t%check('fuzz_tables: checkpoints: some ignored, some damaged, some whole', &
                     all(counts > 0))
    end subroutine fuzz_checkpoints

    ! ---------------------------------------------------------------------------------------
    !> The audit's 100 periods on an asymmetric rig (its note said 5 s, the run took 75 s):
    !! the work estimate counts the budget's model periods, on both kinds of rig: the slope
    !! of each period and of each amplitude (at least 6 n for n periods with u_amplitude),
    !! and linear in n, as the budget is (twice the periods, about twice the work).
    subroutine estimate_many_periods(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(status_t) :: st
        real(dp) :: runs(2, 2)
        character(len=:), allocatable :: what
        integer, parameter :: N = 100
        integer :: k, m
        call read_deck('input/identify_periods.nml', d, st)
        call t%check('fuzz_tables: input/identify_periods.nml read', st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        d%measurement%monte_carlo = 0
        do m = 1, 2
            do k = 1, 2
                call periods_runs(deck_inputs(d, .false.), d%measurement, m*N, m*N, k == 1, &
                                  1.0e-3_dp, runs(k, m), what)
            end do
        end do
        call t%check('fuzz_tables: the work of 100 periods counts the budget''s slopes '// &
                     '(asymmetric rig '//itoa(nint(runs(2, 1)))//', symmetric '// &
                     itoa(nint(runs(1, 1)))//' model periods)', &
                     all(runs(:, 1) >= 6.0_dp*N) .and. index(what, '200 periods') > 0)
        call t%check('fuzz_tables: the work of the periods is linear in their number', &
                     all(runs(:, 2)/runs(:, 1) > 1.8_dp .and. runs(:, 2)/runs(:, 1) < 2.05_dp))
    end subroutine estimate_many_periods

    !> A message is one line (no line end in it), not empty, and names the file.
    logical function one_line_naming(msg, name)
        character(len=*), intent(in) :: msg, name
        one_line_naming = len_trim(msg) > 0 .and. index(msg, NL) == 0 .and. &
            index(msg, achar(13)) == 0 .and. index(msg, name) > 0
    end function one_line_naming

    !> A record taken: finite, times strictly increasing, enough samples.
    logical function sane_record(rec)
        type(record_t), intent(in) :: rec
        integer :: n
        n = size(rec%t)
        sane_record = n >= MIN_SAMPLES .and. size(rec%v) == n
        if (.not. sane_record) return
        sane_record = all(ieee_is_finite(rec%t)) .and. all(ieee_is_finite(rec%v)) .and. &
            all(rec%t(2:n) > rec%t(1:n - 1))
        if (allocated(rec%u)) sane_record = sane_record .and. all(ieee_is_finite(rec%u))
    end function sane_record

    logical function close_to(a, b)
        real(dp), intent(in) :: a(:), b(:)
        close_to = size(a) == size(b)
        if (close_to) close_to = all(abs(a - b) <= 1.0e-8_dp*(1.0_dp + abs(b)))
    end function close_to

    !> Rows 'time value' of a record, times as f0.6, values as es17.9e3.
    function rows(tt, vv) result(s)
        real(dp), intent(in) :: tt(:), vv(:)
        character(len=:), allocatable :: s
        character(len=64) :: a, b
        integer :: i
        s = '# t (s)  W (rad/s)'//NL
        do i = 1, size(tt)
            write (a, '(f0.6)') tt(i)
            write (b, '(es17.9e3)') vv(i)
            s = s//trim(a)//' '//trim(adjustl(b))//NL
        end do
    end function rows

    !> The text with CR LF line ends and tabs for the first blank of each line.
    function crlf_tabs(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: i
        r = ''
        do i = 1, len(s)
            if (s(i:i) == NL) then
                r = r//achar(13)//NL
            else
                r = r//s(i:i)
            end if
        end do
    end function crlf_tabs

    !> Column c (1-based, comma separated) of every data line (not '#', not the header:
    !! the first other line)
    !! times f, rewritten with es24.15.
    function scale_column(s, c, f) result(r)
        character(len=*), intent(in) :: s
        integer, intent(in) :: c
        real(dp), intent(in) :: f
        character(len=:), allocatable :: r, line
        character(len=32) :: num
        integer :: i0, i1, k, a, b, ios
        real(dp) :: x
        logical :: header_seen
        r = ''
        header_seen = .false.
        i0 = 1
        do while (i0 <= len(s))
            i1 = index(s(i0:), NL)
            if (i1 == 0) then
                i1 = len(s)
            else
                i1 = i0 + i1 - 1
            end if
            line = s(i0:i1)
            i0 = i1 + 1
            if (line(1:1) == '#' .or. .not. header_seen) then
                header_seen = header_seen .or. line(1:1) /= '#'
                r = r//line
                cycle
            end if
            a = 1
            do k = 1, c - 1
                b = index(line(a:), ',')
                if (b == 0) exit
                a = a + b
            end do
            b = index(line(a:), ',')
            if (b == 0) then
                b = len(line)
                if (line(b:b) == NL) b = b - 1
            else
                b = a + b - 2
            end if
            read (line(a:b), *, iostat=ios) x
            if (ios /= 0) then
                r = r//line
                cycle
            end if
            write (num, '(es24.15)') x*f
            r = r//line(1:a - 1)//trim(adjustl(num))//line(b + 1:)
        end do
    end function scale_column

    !> The mutations a table of releases and a table of hangs share, k: 1 a byte order mark
    !! and CR LF line ends with tabs (valid), 2 a token that is no number, 3 random bytes,
    !! 4 cut short; any other k the table as it is (valid).  valid is left alone otherwise.
    subroutine table_mutation(base, k, state, text, valid, what)
        character(len=*), intent(in) :: base
        integer, intent(in) :: k
        integer(8), intent(inout) :: state
        character(len=:), allocatable, intent(out) :: text, what
        logical, intent(inout) :: valid
        integer :: i
        select case (k)
        case (1)
            text = char(239)//char(187)//char(191)//crlf_tabs(base)
            valid = .true.
            what = 'BOM, CR LF'
        case (2)
            text = base
            i = 1 + int((len(text) - 1)*rnd(state))
            text = text(1:i)//trim(TOKENS(1 + int(size(TOKENS)*rnd(state))))//text(i + 1:)
            what = 'a token'
        case (3)
            text = base
            do i = 1, 1 + int(3*rnd(state))
                call insert_bytes(text, state)
            end do
            what = 'random bytes'
        case (4)
            text = base(1:int(len(base)*rnd(state)))
            what = 'cut short'
        case default
            text = base
            valid = .true.
            what = 'as it is'
        end select
    end subroutine table_mutation

    !> 1 to 10 random bytes inserted at a random place.
    subroutine insert_bytes(s, state)
        character(len=:), allocatable, intent(inout) :: s
        integer(8), intent(inout) :: state
        integer :: i, j, n
        character(len=:), allocatable :: b
        n = 1 + int(10*rnd(state))
        allocate (character(len=n) :: b)
        do j = 1, n
            b(j:j) = achar(int(256*rnd(state)))
        end do
        i = int((len(s) + 1)*rnd(state))
        s = s(1:i)//b//s(i + 1:)
    end subroutine insert_bytes

    !> A whole file as text ('' when unreadable).
    function file_text(path) result(s)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: s
        integer :: u, ios, n
        s = ''
        open (newunit=u, file=path, access='stream', form='unformatted', status='old', &
              action='read', iostat=ios)
        if (ios /= 0) return
        inquire (unit=u, size=n)
        deallocate (s)
        allocate (character(len=max(n, 0)) :: s)
        if (n > 0) read (u, iostat=ios) s
        close (u)
    end function file_text

    !> A uniform number in [0, 1) from a 64-bit LCG (the same in every build).
    real(dp) function rnd(state)
        integer(8), intent(inout) :: state
        integer(8), parameter :: a = 6364136223846793005_8, c = 1442695040888963407_8
        state = a*state + c     ! wraps modulo 2**64 (two's complement)
        rnd = real(ishft(state, -11), dp)/9007199254740992.0_dp
    end function rnd

end module test_fuzz_tables
