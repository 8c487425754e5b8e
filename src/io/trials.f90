!> The releases of a measurement: the deck's one release (its periods or its record:
!! one_release), or a table of releases (&measurement trials), read and checked whole
!! (read_trial_table).
!!
!! A table of releases is a table (module tables: blanks, tabs, commas or semicolons, CR LF,
!! a byte order mark) whose first line names its columns, from TRIAL_COLUMNS:
!!   trial     the release a row belongs to (any label; rows with the same label are one
!!             release: one release of the body, timed over several stretches);
!!   l, l_prime, b, b_prime, mass
!!             the rig of that release (a column absent: the deck's value for every
!!             release); every row of a release gives the same values;
!!   period    a timed stretch (s): the total time of `cycles` cycles (default the deck's
!!             cycles(1), else 1) at the mean peak amplitude `amplitude` (degrees; default
!!             the deck's &start amplitude), with standard uncertainty `u_period` (s;
!!             default the deck's u_period);
!!   record    a record file of that release (relative to the table's folder), read with
!!             the deck's record_columns and record_units; one row per release.
!! Without a trial column each row is a release of its own.  Every release is periods or
!! one record.  A column not in that list is refused (a misspelt `lenght` would otherwise
!! be the deck's value without a word).
module trials
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, rshort, quoted
    use deck_base, only: record_in_folder
    use tables, only: table_t, read_table
    implicit none
    private

    !> The columns a table of releases may have.
    character(len=9), parameter, public :: TRIAL_COLUMNS(11) = [character(len=9) :: 'trial', &
        'l', 'l_prime', 'b', 'b_prime', 'mass', 'period', 'cycles', 'amplitude', 'u_period', &
        'record']
    !> The rig's inputs a table may give per release (in this order in trial_t%rig).
    character(len=8), parameter, public :: RIG_COLUMNS(5) = [character(len=8) :: 'l', &
        'l_prime', 'b', 'b_prime', 'mass']
    integer, parameter, public :: MAX_TRIALS = 1000     !! releases in a table
    integer, parameter :: MAX_ROWS = 100000             !! rows of a table

    !> One release.
    type, public :: trial_t
        character(len=:), allocatable :: label  !! its label ('1', '2', ... for the deck's)
        integer :: line = 0                     !! its first row's line in the table (0: deck)
        real(dp) :: rig(5) = 0.0_dp             !! l, l_prime, b, b_prime, mass
        real(dp), allocatable :: periods(:)     !! timed totals (s)
        real(dp), allocatable :: cycles(:)      !! cycles each spans
        real(dp), allocatable :: amps(:)        !! mean peak amplitude (degrees)
        real(dp), allocatable :: u_period(:)    !! each total's standard uncertainty (s)
        character(len=:), allocatable :: record !! the record file ('' : periods)
    end type trial_t

    !> The releases of a measurement.
    type, public :: trial_set_t
        type(trial_t), allocatable :: t(:)
        logical :: per_trial(5) = .false.       !! RIG_COLUMNS given per release (columns)
        logical :: from_table = .false.         !! &measurement trials (else the deck's)
    end type trial_set_t

    public :: read_trial_table, one_release

contains

    !> The releases of a table (&measurement trials), read and checked whole: a column
    !! absent takes the deck's value.  ERR_DECK naming the table, its line and column.
    subroutine read_trial_table(table, path, rig, cycles, amplitude, u_period, ts, stat)
        character(len=*), intent(in) :: table   !! &measurement trials as given
        character(len=*), intent(in) :: path    !! the table's file (relative to the deck)
        real(dp), intent(in) :: rig(5)          !! the deck's l, l_prime, b, b_prime, mass
        real(dp), intent(in) :: cycles          !! &measurement cycles(1) (<= 0: 1)
        real(dp), intent(in) :: amplitude       !! &start amplitude (degrees)
        real(dp), intent(in) :: u_period        !! &measurement u_period (s)
        type(trial_set_t), intent(out) :: ts
        type(status_t), intent(out) :: stat     !! ERR_DECK
        type(table_t) :: tab
        integer :: col(size(TRIAL_COLUMNS)), i, j, k, nt, it
        character(len=:), allocatable :: lab
        character(len=512) :: rec
        character(len=64), allocatable :: labels(:)
        real(dp) :: rigv(5), per, cyc, amp, up
        integer, allocatable :: of_row(:)
        stat%code = STATUS_OK
        ts%from_table = .true.
        call read_table(path, tab, stat, MAX_ROWS, ['trial ', 'record'])
        if (stat%code /= STATUS_OK) then
            call fail(stat%msg)
            return
        end if
        do j = 1, tab%ncol
            if (.not. any(TRIAL_COLUMNS == tab%names(j)%s)) then
                call fail('column '//itoa(j)//' is named '//quoted(tab%names(j)%s)// &
                          '; allowed: columns named '//names_list())
                return
            end if
            if (count([(tab%names(k)%s == tab%names(j)%s, k=1, tab%ncol)]) > 1) then
                call fail('column '//quoted(tab%names(j)%s)//' is named twice; allowed: '// &
                          'each column once')
                return
            end if
        end do
        do k = 1, size(TRIAL_COLUMNS)
            col(k) = tab%column(TRIAL_COLUMNS(k))
        end do
        if (col(7) == 0 .and. col(11) == 0) then
            call fail('neither a column period nor a column record; allowed: a column '// &
                      'period (timed totals, s) or record (a record file per release)')
            return
        end if
        ts%per_trial = col(2:6) > 0
        ! the releases, in the order of their first rows
        allocate (labels(0))
        allocate (of_row(tab%nrow))
        do i = 1, tab%nrow
            if (col(1) > 0) then
                lab = trim(tab%text(i, col(1))%s)
                if (len(lab) == 0 .or. len(lab) > 64) then
                    call fail_at(i, 'trial', '''', 'a label of 1 to 64 characters')
                    return
                end if
            else
                lab = itoa(i)
            end if
            it = 0
            do k = 1, size(labels)
                if (trim(labels(k)) == lab) it = k
            end do
            if (it == 0) then
                if (size(labels) == MAX_TRIALS) then
                    call fail('more than '//itoa(MAX_TRIALS)//' releases; allowed: at most '// &
                              itoa(MAX_TRIALS))
                    return
                end if
                labels = [character(len=64) :: labels, lab]
                it = size(labels)
            end if
            of_row(i) = it
        end do
        nt = size(labels)
        allocate (ts%t(nt))
        do it = 1, nt
            ts%t(it)%label = trim(labels(it))
            allocate (ts%t(it)%periods(0), ts%t(it)%cycles(0), ts%t(it)%amps(0), &
                      ts%t(it)%u_period(0))
            ts%t(it)%record = ''
        end do
        do i = 1, tab%nrow
            it = of_row(i)
            ! the rig of the row: a column or the deck
            rigv = rig
            do k = 1, 5
                if (col(k + 1) == 0) cycle
                rigv(k) = tab%v(i, col(k + 1))
                if (.not. (rigv(k) > 0.0_dp .and. rigv(k) <= 1.0e100_dp)) then
                    call fail_at(i, TRIAL_COLUMNS(k + 1), rshort(rigv(k)), 'a length or mass '// &
                                 '> 0 in the deck''s units')
                    return
                end if
            end do
            if (ts%t(it)%line == 0) then
                ts%t(it)%line = tab%line(i)
                ts%t(it)%rig = rigv
            else if (any(rigv /= ts%t(it)%rig)) then
                k = findloc(rigv /= ts%t(it)%rig, .true., 1)
                call fail_at(i, RIG_COLUMNS(k), rshort(rigv(k)), 'the same rig on every '// &
                             'row of a release (trial '//quoted(ts%t(it)%label)//' has '// &
                             rshort(ts%t(it)%rig(k))//' on line '//itoa(ts%t(it)%line)//')')
                return
            end if
            rec = ''
            if (col(11) > 0) rec = trim(tab%text(i, col(11))%s)
            if (len_trim(rec) > 0) then
                if (len(ts%t(it)%record) > 0 .or. size(ts%t(it)%periods) > 0) then
                    call fail_at(i, 'record', quoted(trim(rec)), 'one record per release, not '// &
                                 'with periods (trial '//quoted(ts%t(it)%label)//')')
                    return
                end if
                ts%t(it)%record = record_in_folder(path, trim(rec))
                cycle
            end if
            if (col(7) == 0) then
                call fail_at(i, 'record', '''''', 'a record file on every row (the table '// &
                             'has no column period)')
                return
            end if
            if (len(ts%t(it)%record) > 0) then
                call fail_at(i, 'period', rshort(tab%v(i, col(7))), 'periods or one '// &
                             'record per release, not both (trial '// &
                             quoted(ts%t(it)%label)//')')
                return
            end if
            per = tab%v(i, col(7))
            if (.not. (per > 0.0_dp .and. per <= 1.0e100_dp)) then
                call fail_at(i, 'period', rshort(per), 'period > 0 (s, the total time of '// &
                             '`cycles` cycles)')
                return
            end if
            cyc = 1.0_dp
            if (cycles > 0.0_dp) cyc = cycles
            if (col(8) > 0) cyc = tab%v(i, col(8))
            if (.not. (cyc >= 0.5_dp .and. cyc <= 1.0e6_dp)) then
                call fail_at(i, 'cycles', rshort(cyc), '0.5 <= cycles <= 1e6')
                return
            end if
            amp = amplitude
            if (col(9) > 0) amp = tab%v(i, col(9))
            if (.not. (amp > 0.0_dp .and. amp < 180.0_dp)) then
                call fail_at(i, 'amplitude', rshort(amp), '0 < amplitude < 180 (degrees of '// &
                             'theta4, the mean peak over the cycles timed)')
                return
            end if
            up = u_period
            if (col(10) > 0) up = tab%v(i, col(10))
            if (.not. (up >= 0.0_dp .and. up < per)) then
                call fail_at(i, 'u_period', rshort(up), '0 <= u_period < period (s)')
                return
            end if
            ts%t(it)%periods = [ts%t(it)%periods, per]
            ts%t(it)%cycles = [ts%t(it)%cycles, cyc]
            ts%t(it)%amps = [ts%t(it)%amps, amp]
            ts%t(it)%u_period = [ts%t(it)%u_period, up]
        end do
    contains
        subroutine fail(what)
            character(len=*), intent(in) :: what
            call set_error(stat, ERR_DECK, '&measurement trials = '//quoted(table)//': '// &
                           what)
        end subroutine fail
        subroutine fail_at(row, name, value, allowed)
            integer, intent(in) :: row
            character(len=*), intent(in) :: name, value, allowed
            call fail('line '//itoa(tab%line(row))//', column '//trim(name)//' = '// &
                      trim(value)//'; allowed: '//allowed)
        end subroutine fail_at
    end subroutine read_trial_table

    !> The deck's one release: its periods (each the total of cycles(i) cycles, with
    !! u_period each) or, without periods, its record.
    pure subroutine one_release(rig, periods, cycles, amps, u_period, record, ts)
        real(dp), intent(in) :: rig(5)          !! l, l_prime, b, b_prime, mass
        real(dp), intent(in) :: periods(:), cycles(:), amps(:)  !! s, cycles, degrees
        real(dp), intent(in) :: u_period        !! s, of each period
        character(len=*), intent(in) :: record  !! the record file ('' : none)
        type(trial_set_t), intent(out) :: ts
        integer :: n
        allocate (ts%t(1))
        n = size(periods)
        associate (t => ts%t(1))
            t%label = '1'
            t%line = 0
            t%rig = rig
            t%periods = periods
            t%cycles = cycles
            t%amps = amps
            allocate (t%u_period(n))
            t%u_period = u_period
            t%record = ''
            if (n == 0) t%record = record
        end associate
    end subroutine one_release

    !> The allowed column names, quoted and separated by commas.
    pure function names_list() result(s)
        character(len=:), allocatable :: s
        integer :: k
        s = ''
        do k = 1, size(TRIAL_COLUMNS)
            if (k > 1) s = s//', '
            s = s//trim(TRIAL_COLUMNS(k))
        end do
    end function names_list


end module trials
