!> A measurement read into its model (module measurement): identify's periods, record or
!! table of releases (read_releases), tensor's table of hangs (read_hangs), and the tares.
!! Every table goes through the one reader (module column_table: columns by name, the same
!! checks and messages); a period is divided by its cycles here, once.
!!
!! A table of releases (&measurement trials) has columns named from RELEASE_COLUMNS:
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
!!             the deck's record_columns and record_units; one row per release;
!!   estimate  the parameters the release's fit estimates (default the deck's estimate);
!!   session   the session the release belongs to (default the deck's session).
!! Without a trial column each row is a release of its own.  Every release is periods or
!! one record, and a table holds one kind.  A column not in that list is refused (a
!! misspelt `lenght` would otherwise be the deck's value without a word).
!!
!! A table of hangs (&tensor hangs) has columns named from HANG_COLUMNS:
!! * `hang`: rows with the same value are repeated timings of one hang (absent: each row is
!!   a hang of its own);
!! * `up_x, up_y, up_z`: the body-frame direction that points up at rest (any length but
!!   0), and `along_x, along_y, along_z`: the body-frame direction from the attachment point
!!   C toward D (orthogonalised against up);
!! * or instead `c_x, c_y, c_z, d_x, d_y, d_z`: the body-frame points C and D where the
!!   cables were attached, with the mass centre in the body frame from &tensor cg.  At rest
!!   the mass centre hangs in the vertical plane through CD, so C, D and the mass centre fix
!!   up (the normal to CD in that plane, away from the mass centre), along (D - C),
!!   b_prime (|D - C|), cg_depth and cg_offset;
!! * `period`: the total time of `cycles` cycles (default 1) in s; `amplitude`: the peak
!!   theta4 at which it was timed, degrees (default 0: small amplitude); `u_period`: the
!!   standard uncertainty of the period column's value (default &tensor u_period);
!! * any of `l, l_prime, b, b_prime, cg_depth, cg_offset`: the hang's own rig (a column
!!   absent takes the deck's value for every hang);
!! * with &tensor estimate = 'tensor cg', the hang's attitude at rest: `gx, gy, gz`, the
!!   direction of gravity in the body frame, or `tilt`, the roll about CD in degrees
!!   (gravity = -cos(tilt) up + sin(tilt) (up x along)).
!! In the model's terms (Kane & Tseng's ntilde frame of the hang): ntilde_1 = -up points
!! down at rest, ntilde_3 = -along points from D to C, ntilde_2 = ntilde_3 x ntilde_1.
!!
!! Failures are ERR_DECK statuses of one line naming the table (or the deck's key), its
!! line and column, what is wrong and what is allowed.  No routine stops.
module measurement_read
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, rshort, rlist_short, quoted, lower, sci
    use deck_base, only: record_in_folder
    use rig_groups, only: suspension_group_t, body_group_t
    use measure_groups, only: measurement_group_t, tensor_group_t, check_estimate, AMPLITUDE_MIN
    use rig, only: rig_t, start_t
    use budget, only: input_t
    use inputs, only: set_input
    use column_table, only: column_table_t, read_column_table
    use vectors, only: cross
    use measurement, only: measurement_t, release_t, observation_t, hang_t, OBS_TIMING, &
        OBS_RECORD, OBS_HANG, OBS_TARE, RIG_COLUMNS
    implicit none
    private

    !> The columns a table of releases may have.
    character(len=*), parameter, public :: RELEASE_COLUMNS = 'trial l l_prime b b_prime '// &
        'mass period cycles amplitude u_period record estimate session'
    !> Its columns of text.
    character(len=8), parameter :: RELEASE_TEXT(4) = [character(len=8) :: 'trial', 'record', &
        'estimate', 'session']
    integer, parameter, public :: MAX_TRIALS = 1000     !! releases in a table
    integer, parameter :: MAX_ROWS = 100000             !! rows of a table of releases

    !> The column names a table of hangs may use.
    character(len=*), parameter, public :: HANG_COLUMNS = 'hang up_x up_y up_z along_x '// &
        'along_y along_z period cycles amplitude u_period l l_prime b b_prime cg_depth '// &
        'cg_offset cg_offset_y c_x c_y c_z d_x d_y d_z gx gy gz tilt'
    !> Most rows of a table of hangs.
    integer, parameter, public :: MAX_HANG_ROWS = 10000
    !> Largest amplitude of a hang's row (degrees; the period's own limit is the analysis's).
    real(dp), parameter :: AMPLITUDE_MAX = 90.0_dp
    !> along counts as parallel to up when its part normal to up is below this fraction.
    real(dp), parameter :: PARALLEL_TOL = 1.0e-6_dp
    !> A hang's cycle may not be shorter than this fraction of its pendulum time
    !! 2 pi sqrt(l/g): the torsion period is 2 pi sqrt(l/g) 2 rho/sqrt(b b') for a radius of
    !! gyration rho, and no hung body has rho below 1/2000 of sqrt(b b').
    real(dp), parameter :: PERIOD_MIN_RIG = 1.0e-3_dp
    !> Lengths of a hang over b_prime, and the body-frame points' size: as the deck's ratios.
    real(dp), parameter :: RATIO_MIN = 1.0e-3_dp, RATIO_MAX = 1.0e3_dp

    public :: read_releases, read_hangs, hang_defaults, table_name, release_inputs

contains

    ! ------------------------------------------------------------------ releases (identify)

    !> identify's measurement: the table of releases (&measurement trials) when given, else
    !! the deck's one release (its periods, each the total of cycles(i) cycles with
    !! u_period each, or its record); the common inputs x with their u; the tares.
    !! ERR_DECK naming the table, its line and column.  amplitude_given: the deck gives
    !! the release amplitude (&start amplitude); without it a table of periods needs its
    !! column amplitude (absent: .true.).
    subroutine read_releases(mea, rg, st, cables, x, m, stat, amplitude_given)
        type(measurement_group_t), intent(in) :: mea    !! the deck's &measurement
        type(rig_t), intent(in) :: rg           !! the deck's rig
        type(start_t), intent(in) :: st         !! the deck's start
        integer, intent(in) :: cables           !! &suspension cables (> 2: a platform)
        type(input_t), intent(in) :: x(:)       !! the budget's inputs (deck values, u)
        type(measurement_t), intent(out) :: m
        type(status_t), intent(out) :: stat     !! ERR_DECK
        logical, intent(in), optional :: amplitude_given
        logical :: amp_given
        stat%code = STATUS_OK
        amp_given = .true.
        if (present(amplitude_given)) amp_given = amplitude_given
        m%inputs = x
        call read_tares(mea, m)
        if (len_trim(mea%trials) == 0) then
            call one_release(mea, rg, st, m)
        else
            call read_release_table(mea, rg, st, cables, amp_given, m, stat)
        end if
    end subroutine read_releases

    !> The tares of &measurement: a fixture measured alone (tare_i1, u_tare_i1, its mass)
    !! and a known added moment (added_inertia, u_added_inertia), each when given.
    pure subroutine read_tares(mea, m)
        type(measurement_group_t), intent(in) :: mea
        type(measurement_t), intent(inout) :: m
        logical :: given(2)
        integer :: k
        given = [mea%tare_i1 > 0.0_dp .or. mea%u_tare_i1 > 0.0_dp, &
                 mea%added_inertia > 0.0_dp .or. mea%u_added_inertia > 0.0_dp]
        allocate (m%tares(count(given)))
        k = 0
        if (given(1)) then
            k = k + 1
            m%tares(k)%kind = OBS_TARE
            m%tares(k)%name = 'tare_I1'
            m%tares(k)%value = mea%tare_i1
            m%tares(k)%u = mea%u_tare_i1
            m%tares(k)%mass = mea%tare_mass
        end if
        if (given(2)) then
            k = k + 1
            m%tares(k)%kind = OBS_TARE
            m%tares(k)%name = 'added_inertia'
            m%tares(k)%value = mea%added_inertia
            m%tares(k)%u = mea%u_added_inertia
            m%tares(k)%added = .true.
        end if
    end subroutine read_tares

    !> The deck's one release: its periods (each the total of cycles(i) cycles, with
    !! u_period each) or, without periods, its record.
    pure subroutine one_release(mea, rg, st, m)
        type(measurement_group_t), intent(in) :: mea
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        type(measurement_t), intent(inout) :: m
        type(observation_t), allocatable :: o(:)
        integer :: n, i
        m%source = ''
        m%from_table = .false.
        allocate (m%releases(1))
        associate (r => m%releases(1))
            r%label = '1'
            r%line = 0
            r%rig = rg
            r%start = st
            r%estimate = trim(mea%estimate)
            r%session = trim(mea%session)
        end associate
        n = mea%n_periods
        if (n > 0) then
            allocate (o(n))
            do i = 1, n
                o(i)%kind = OBS_TIMING
                o(i)%release = 1
                call set_timing(o(i), mea%periods(i), mea%cycles(i), mea%amplitudes(i), &
                                mea%u_period)
            end do
        else
            allocate (o(1))
            o(1)%kind = OBS_RECORD
            o(1)%release = 1
            o(1)%file = trim(mea%record)
            if (allocated(mea%record_path)) o(1)%file = mea%record_path
        end if
        call move_alloc(o, m%obs)
    end subroutine one_release

    !> A timing: the total of `cycles` cycles with its u, at `amplitude`; the period and its
    !! u per cycle, divided here once.
    elemental subroutine set_timing(o, total, cycles, amplitude, u_total)
        type(observation_t), intent(inout) :: o
        real(dp), intent(in) :: total, cycles, amplitude, u_total
        o%total = total
        o%cycles = cycles
        o%period = total/cycles
        o%amplitude = amplitude
        o%u_total = u_total
        o%u_period = u_total/cycles
    end subroutine set_timing

    !> The releases of a table (&measurement trials), read and checked whole: a column
    !! absent takes the deck's value; the column amplitude only when the deck gives one
    !! (amp_given: &start amplitude), the start's default being nobody's amplitude.
    subroutine read_release_table(mea, rg, st, cables, amp_given, m, stat)
        type(measurement_group_t), intent(in) :: mea
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        integer, intent(in) :: cables
        logical, intent(in) :: amp_given
        type(measurement_t), intent(inout) :: m
        type(status_t), intent(inout) :: stat
        type(column_table_t) :: ct
        type(observation_t) :: o
        type(observation_t), allocatable :: obs(:)
        type(start_t) :: st0
        character(len=:), allocatable :: lab, rec, word
        character(len=64), allocatable :: labels(:)
        real(dp) :: deckv(5), per, cyc, amp, up
        real(dp), allocatable :: rigv(:, :)
        integer, allocatable :: of_row(:)
        logical, allocatable :: has_periods(:), has_record(:)
        integer :: i, k, nt, it, no
        rec = ''
        m%source = '&measurement trials = '//quoted(mea%trials)
        m%from_table = .true.
        call read_column_table(mea%trials_path, m%source//': ', RELEASE_COLUMNS, ct, stat, &
                               MAX_ROWS, RELEASE_TEXT)
        if (stat%code /= STATUS_OK) return
        if (.not. ct%has('period') .and. .not. ct%has('record')) then
            call ct%fail(stat, 'neither a column period nor a column record; allowed: a '// &
                         'column period (timed totals, s) or record (a record file per release)')
            return
        end if
        if (ct%has('period') .and. .not. ct%has('amplitude') .and. .not. amp_given) then
            call ct%fail(stat, 'no column amplitude, and the deck gives none (&start '// &
                         'amplitude); allowed: a column amplitude (degrees of theta4, the '// &
                         'mean peak over the cycles timed) or &start amplitude = A for '// &
                         'every release; likely: the column left out or named otherwise')
            return
        end if
        ! the releases, in the order of their first rows
        allocate (labels(0), of_row(ct%nrow))
        do i = 1, ct%nrow
            if (ct%has('trial')) then
                lab = ct%text(i, 'trial')
                if (len(lab) == 0 .or. len(lab) > 64) then
                    call ct%bad_value(stat, i, 'trial', '''', 'a label of 1 to 64 characters')
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
                    call ct%fail(stat, 'more than '//itoa(MAX_TRIALS)//' releases; allowed: '// &
                                 'at most '//itoa(MAX_TRIALS))
                    return
                end if
                labels = [character(len=64) :: labels, lab]
                it = size(labels)
            end if
            of_row(i) = it
        end do
        nt = size(labels)
        allocate (m%releases(nt), rigv(5, nt), has_periods(nt), has_record(nt), obs(ct%nrow))
        has_periods = .false.
        has_record = .false.
        deckv = [rg%l, rg%l_prime, rg%b, rg%b_prime, rg%mass]
        do it = 1, nt
            associate (r => m%releases(it))
                r%label = trim(labels(it))
                r%own = [(ct%has(RIG_COLUMNS(k)), k=1, 5)]
                r%start = st
            end associate
        end do
        no = 0
        do i = 1, ct%nrow
            it = of_row(i)
            associate (r => m%releases(it))
                ! the rig of the row: a column or the deck
                do k = 1, 5
                    if (.not. ct%has(RIG_COLUMNS(k))) cycle
                    call ct%check_value(stat, i, RIG_COLUMNS(k), ct%v(i, RIG_COLUMNS(k), &
                        deckv(k)), ct%v(i, RIG_COLUMNS(k), deckv(k)) > 0.0_dp .and. &
                        ct%v(i, RIG_COLUMNS(k), deckv(k)) <= 1.0e100_dp, 'a length or mass '// &
                        '> 0 in the deck''s units')
                end do
                if (stat%code /= STATUS_OK) return
                if (ct%has('mass') .and. mea%tare_mass >= ct%v(i, 'mass', deckv(5))) then
                    ! the release's mass is all that hung: the fixture's is a part of it
                    call ct%bad_value(stat, i, 'mass', rshort(ct%v(i, 'mass', deckv(5))), &
                        'mass above &measurement tare_mass = '//rshort(mea%tare_mass)// &
                        ' (the mass column is all that hung: body and fixture)')
                    return
                end if
                if (r%line == 0) then
                    r%line = ct%line(i)
                    rigv(:, it) = [(ct%v(i, RIG_COLUMNS(k), deckv(k)), k=1, 5)]
                else
                    do k = 1, 5
                        if (ct%v(i, RIG_COLUMNS(k), deckv(k)) == rigv(k, it)) cycle
                        call ct%bad_value(stat, i, RIG_COLUMNS(k), &
                            rshort(ct%v(i, RIG_COLUMNS(k), deckv(k))), 'the same rig on every '// &
                            'row of a release (trial '//quoted(r%label)//' has '// &
                            rshort(rigv(k, it))//' on line '//itoa(r%line)//')')
                        return
                    end do
                end if
                ! the release's settings: its estimate and session
                call setting(i, 'estimate', trim(mea%estimate), r%estimate)
                if (stat%code /= STATUS_OK) return
                call setting(i, 'session', trim(mea%session), r%session)
                if (stat%code /= STATUS_OK) return
                rec = ct%text(i, 'record')
                if (len_trim(rec) > 0) then
                    if (has_record(it) .or. has_periods(it)) then
                        call ct%bad_value(stat, i, 'record', quoted(trim(rec)), 'one record '// &
                            'per release, not with periods (trial '//quoted(r%label)//')')
                        return
                    end if
                    has_record(it) = .true.
                    o = observation_t(kind=OBS_RECORD, release=it, line=ct%line(i), &
                                      file=record_in_folder(mea%trials_path, trim(rec)))
                    ! one record is one release: listed twice it would count twice
                    do k = 1, no
                        if (obs(k)%kind /= OBS_RECORD) cycle
                        if (obs(k)%file /= o%file) cycle
                        call ct%fail_row(stat, i, 'column record = '//quoted(trim(rec))// &
                            ': the same record as line '//itoa(obs(k)%line)//' (trial '// &
                            quoted(m%releases(obs(k)%release)%label)//'): one record is one '// &
                            'release, counted once; allowed: each record file on one row')
                        return
                    end do
                    no = no + 1
                    obs(no) = o
                    cycle
                end if
                if (.not. ct%has('period')) then
                    call ct%bad_value(stat, i, 'record', '''''', 'a record file on every row '// &
                                      '(the table has no column period)')
                    return
                end if
                per = ct%v(i, 'period', 0.0_dp)
                if (has_record(it)) then
                    call ct%bad_value(stat, i, 'period', rshort(per), 'periods or one record '// &
                                      'per release, not both (trial '//quoted(r%label)//')')
                    return
                end if
                call ct%check_value(stat, i, 'period', per, per > 0.0_dp .and. &
                    per <= 1.0e100_dp, 'period > 0 (s, the total time of `cycles` cycles)')
                if (stat%code /= STATUS_OK) return
                cyc = 1.0_dp
                if (mea%cycles(1) > 0.0_dp) cyc = mea%cycles(1)
                cyc = ct%v(i, 'cycles', cyc)
                call ct%check_value(stat, i, 'cycles', cyc, cyc >= 0.5_dp .and. &
                                    cyc <= 1.0e6_dp, '0.5 <= cycles <= 1e6')
                if (stat%code /= STATUS_OK) return
                amp = ct%v(i, 'amplitude', st%amplitude)
                call ct%check_value(stat, i, 'amplitude', amp, amp >= AMPLITUDE_MIN .and. &
                    amp < 180.0_dp, rshort(AMPLITUDE_MIN)//' <= amplitude < 180 (degrees of '// &
                    'theta4, the mean peak over the cycles timed; smaller swings the model '// &
                    'does not resolve)')
                if (stat%code /= STATUS_OK) return
                up = ct%v(i, 'u_period', mea%u_period)
                call ct%check_value(stat, i, 'u_period', up, up >= 0.0_dp .and. up < per, &
                                    '0 <= u_period < period (s)')
                if (stat%code /= STATUS_OK) return
                has_periods(it) = .true.
                o = observation_t(kind=OBS_TIMING, release=it, line=ct%line(i), file='')
                call set_timing(o, per, cyc, amp, up)
                no = no + 1
                obs(no) = o
            end associate
        end do
        m%obs = obs(1:no)
        if (any(has_record) .and. any(has_periods)) then
            call set_error(stat, ERR_DECK, m%source//': releases of periods and releases '// &
                'of records in one table; allowed: one kind of release per table (a deck per '// &
                'kind)')
            return
        end if
        ! each release's rig: the deck's, with the table's values of l, l_prime, b, b_prime,
        ! mass (a changed b_prime keeps the mass centre's depth below, and offset along, CD)
        do it = 1, nt
            associate (r => m%releases(it))
                r%rig = rg
                st0 = st
                do k = 1, 5
                    if (rigv(k, it) == deckv(k)) cycle
                    if (cables > 2 .and. k <= 2) then
                        ! a platform: one length for every cable (the column l; l_prime
                        ! follows it)
                        if (k == 1) call set_input(r%rig, st0, 'length', rigv(1, it))
                    else
                        call set_input(r%rig, st0, RIG_COLUMNS(k), rigv(k, it))
                    end if
                end do
            end associate
        end do
    contains
        !> A release's setting from its column `name` (the same on every row of the
        !! release; an empty field or no column: the deck's `deck` value).
        subroutine setting(i, name, deck, val)
            integer, intent(in) :: i
            character(len=*), intent(in) :: name, deck
            character(len=:), allocatable, intent(inout) :: val
            logical :: given
            word = ct%text(i, name)
            given = len(word) > 0
            if (.not. given) word = deck
            if (given .and. len(word) > 64) then
                call ct%bad_value(stat, i, name, quoted(word(1:64)//'...'), 'at most 64 '// &
                                  'characters')
                return
            end if
            if (name == 'estimate' .and. given) then
                call check_estimate(stat, word, ct%head//'line '//itoa(ct%line(i))// &
                                    ', column estimate = '//quoted(word)//': ')
                if (stat%code /= STATUS_OK) return
                if (index(' '//lower(word)//' ', ' i1 ') == 0) then
                    call ct%bad_value(stat, i, name, quoted(word), '''I1'' followed by any '// &
                        'of c_v, c_q, amplitude, t0, bias (with a record)')
                    return
                end if
            end if
            if (.not. allocated(val)) then
                val = word
            else if (val /= word) then
                call ct%bad_value(stat, i, name, quoted(word), 'the same '//name//' on '// &
                    'every row of a release (trial '//quoted(m%releases(of_row(i))%label)// &
                    ' has '//quoted(val)//' on line '//itoa(m%releases(of_row(i))%line)//')')
            end if
        end subroutine setting
    end subroutine read_release_table

    !> The budget's inputs x (names, u) with the values of the release's rig rg: its own
    !! values of RIG_COLUMNS (a platform's one length, l), the deck's otherwise.
    pure function release_inputs(x, rg) result(xr)
        type(input_t), intent(in) :: x(:)
        type(rig_t), intent(in) :: rg
        type(input_t), allocatable :: xr(:)
        integer :: j
        xr = x
        do j = 1, size(xr)
            select case (trim(xr(j)%name))
            case ('l', 'length')
                xr(j)%value = rg%l
            case ('l_prime')
                xr(j)%value = rg%l_prime
            case ('b')
                xr(j)%value = rg%b
            case ('b_prime')
                xr(j)%value = rg%b_prime
            case ('mass')
                xr(j)%value = rg%mass
            end select
        end do
    end function release_inputs

    ! ------------------------------------------------------------------ hangs (tensor)

    !> '&tensor hangs = 'FILE'': the head of every message about the table.
    function table_name(ten) result(s)
        type(tensor_group_t), intent(in) :: ten     !! the deck's &tensor
        character(len=:), allocatable :: s
        s = '&tensor hangs = '//quoted(trim(ten%hangs))
    end function table_name

    !> A hang with the deck's rig (l, l_prime, b, b_prime and the mass centre of &body:
    !! cg_depth, cg_offset, or r, lambda); have_cg = .false. when the deck gave no mass
    !! centre.
    pure subroutine hang_defaults(sus, bod, h, have_cg)
        type(suspension_group_t), intent(in) :: sus     !! the deck's, normalised
        type(body_group_t), intent(in) :: bod           !! the deck's, normalised
        type(hang_t), intent(out) :: h
        logical, intent(out) :: have_cg
        h%l = sus%l
        h%l_prime = sus%l_prime
        h%b = sus%b
        h%b_prime = sus%b_prime
        have_cg = bod%gave('cg_depth') .or. bod%gave('cg_offset') .or. &
                  (bod%gave('r') .and. bod%gave('lambda'))
        h%cg_depth = bod%r*sin(bod%lambda)
        h%cg_offset = bod%r*cos(bod%lambda) - 0.5_dp*sus%b_prime
        h%cables = sus%cables
        if (sus%cables > 2) h%cg_offset_y = bod%cg_offset_y
    end subroutine hang_defaults

    !> Read the deck's table of hangs (&tensor hangs_path) and check it: the columns, each
    !! row's values, rows of one hang with one pose; each hang a release (its pose in
    !! %hang), each row a timing of it (OBS_HANG).
    subroutine read_hangs(ten, sus, bod, m, stat)
        type(tensor_group_t), intent(in) :: ten         !! the deck's &tensor
        type(suspension_group_t), intent(in) :: sus     !! the rig's defaults (normalised)
        type(body_group_t), intent(in) :: bod
        type(measurement_t), intent(out) :: m
        type(status_t), intent(out) :: stat     !! ERR_DECK naming the table and the line
        type(column_table_t) :: ct
        type(hang_t) :: h0, h
        type(hang_t), allocatable :: hangs(:)
        real(dp) :: up_v(3), al_v(3), c_v(3), d_v(3), per, u_tot, t_rig, g_v(3), tl
        logical :: have_cg, form_up, form_pts, have_g
        integer, allocatable :: ids(:)
        integer :: i, k, n, nh
        stat%code = STATUS_OK
        m%source = table_name(ten)
        m%from_table = .true.
        call read_column_table(ten%hangs_path, m%source//': ', HANG_COLUMNS, ct, stat, &
                               MAX_HANG_ROWS)
        if (stat%code /= STATUS_OK) return
        form_up = any([(ct%has(trim(vec_name('up', k))), k=1, 3)]) .or. &
                  any([(ct%has(trim(vec_name('along', k))), k=1, 3)])
        form_pts = any([(ct%has(trim(vec_name('c', k))), k=1, 3)]) .or. &
                   any([(ct%has(trim(vec_name('d', k))), k=1, 3)])
        if (form_up .and. form_pts) then
            call ct%fail(stat, 'both up/along and c/d columns; allowed: the orientation '// &
                'either as up_x, up_y, up_z, along_x, along_y, along_z or as the attachment '// &
                'points c_x, c_y, c_z, d_x, d_y, d_z, not both')
            return
        end if
        if (.not. (form_up .or. form_pts)) then
            call ct%fail(stat, 'no column of the orientation; allowed: up_x, up_y, up_z, '// &
                'along_x, along_y, along_z (the body-frame directions up and from C toward '// &
                'D) or c_x, c_y, c_z, d_x, d_y, d_z (the attachment points)')
            return
        end if
        if (sus%cables > 2) then
            call platform_columns()
            if (stat%code /= STATUS_OK) return
        else if (ct%has('cg_offset_y')) then
            call ct%fail(stat, 'column ''cg_offset_y'' on two cables; allowed: cg_offset_y '// &
                'on a platform of three cables (&suspension cables = 3), cg_depth and '// &
                'cg_offset on a bifilar')
            return
        end if
        if (form_up) then
            call ct%need(stat, 'up_x up_y up_z')
            call ct%need(stat, 'along_x along_y along_z')
        else
            call ct%need(stat, 'c_x c_y c_z')
            call ct%need(stat, 'd_x d_y d_z')
            if (stat%code /= STATUS_OK) return
            if (.not. ten%cg_given) then
                call ct%fail(stat, 'hangs given by the attachment points C and D need the '// &
                    'mass centre in the body frame; allowed: &tensor cg = x, y, z with the '// &
                    'c_x ... d_z columns')
                return
            end if
            if (ct%has('b_prime') .or. ct%has('cg_depth') .or. ct%has('cg_offset')) then
                call ct%fail(stat, 'column '//quoted(trim(merge('b_prime  ', 'cg_depth ', &
                    ct%has('b_prime'))))//' with the attachment points; allowed: b_prime, '// &
                    'cg_depth and cg_offset follow from C, D and &tensor cg (give them only '// &
                    'with up/along)')
                return
            end if
        end if
        if (stat%code /= STATUS_OK) return
        call ct%need(stat, 'period', 'a column ''period'' (the time of ''cycles'' cycles, s)')
        if (stat%code /= STATUS_OK) return
        have_g = ct%has('gx') .or. ct%has('gy') .or. ct%has('gz')
        if (have_g .and. ct%has('tilt')) then
            call ct%fail(stat, 'both gx, gy, gz and tilt columns; allowed: the attitude at '// &
                'rest either as the gravity direction in the body frame (gx, gy, gz) or as '// &
                'the roll about CD (tilt), not both')
            return
        end if
        if (have_g) call ct%need(stat, 'gx gy gz')
        if (stat%code /= STATUS_OK) return
        if ((have_g .or. ct%has('tilt')) .and. .not. ten%estimates_cg()) then
            call ct%fail(stat, 'columns of the attitude at rest ('//trim(merge('gx, gy, gz', &
                'tilt      ', have_g))//') with &tensor estimate = '''//trim(ten%estimate)// &
                '''; allowed: &tensor estimate = ''tensor cg'' (the mass centre fitted from '// &
                'them and the periods), or no attitude columns')
            return
        end if
        if (form_up .and. ten%cg_given) then
            call set_error(stat, ERR_DECK, '&tensor cg = '//rlist_short(ten%cg)// &
                ': the mass centre in the body frame is used with hangs given by their '// &
                'attachment points; allowed: cg with the c_x ... d_z columns, or cg_depth, '// &
                'cg_offset (&body or columns) with up/along')
            return
        end if
        call hang_defaults(sus, bod, h0, have_cg)
        ! without a mass centre in the deck, a cg_depth column with the offset 0 by default
        if (.not. have_cg) h0%cg_offset = 0.0_dp
        if (form_up .and. .not. have_cg .and. .not. ct%has('cg_depth')) then
            call set_error(stat, ERR_DECK, 'not given: &body the mass centre (cg_depth and '// &
                'cg_offset, or r and lambda); a deck with analyses = ''tensor'' gives every '// &
                'physical input itself (the defaults are the paper''s dimensionless scene); '// &
                'allowed: &body cg_depth, cg_offset for every hang, or columns cg_depth (and '// &
                'cg_offset) in '//table_name(ten)//', or c_x ... d_z with &tensor cg')
            return
        end if
        ! the rows
        n = ct%nrow
        allocate (m%obs(n), hangs(n), ids(n))
        m%points = form_pts
        nh = 0
        do i = 1, n
            h = h0
            h%line = ct%line(i)
            h%id = i
            if (ct%has('hang')) then
                call ct%check_value(stat, i, 'hang', ct%v(i, 'hang', 0.0_dp), &
                    abs(ct%v(i, 'hang', 0.0_dp)) <= 1.0e9_dp .and. &
                    ct%v(i, 'hang', 0.0_dp) == anint(ct%v(i, 'hang', 0.0_dp)), &
                    'a whole number naming the hang, |hang| <= 1e9')
                if (stat%code /= STATUS_OK) return
                h%id = nint(ct%v(i, 'hang', 0.0_dp))
            end if
            h%l = ct%v(i, 'l', h%l)
            h%l_prime = ct%v(i, 'l_prime', h%l_prime)
            h%b = ct%v(i, 'b', h%b)
            h%b_prime = ct%v(i, 'b_prime', h%b_prime)
            h%own = [ct%has('l'), ct%has('l_prime'), ct%has('b'), ct%has('b_prime')]
            if (h%cables > 2) h%l_prime = h%l
            h%cg_depth = ct%v(i, 'cg_depth', h%cg_depth)
            h%cg_offset = ct%v(i, 'cg_offset', h%cg_offset)
            h%cg_offset_y = ct%v(i, 'cg_offset_y', h%cg_offset_y)
            do k = 1, 3
                if (form_up) then
                    up_v(k) = ct%v(i, trim(vec_name('up', k)), 0.0_dp)
                    al_v(k) = ct%v(i, trim(vec_name('along', k)), 0.0_dp)
                else
                    c_v(k) = ct%v(i, trim(vec_name('c', k)), 0.0_dp)
                    d_v(k) = ct%v(i, trim(vec_name('d', k)), 0.0_dp)
                end if
            end do
            if (form_up) then
                call orientation(i, up_v, al_v, h)
            else
                call from_points(i, c_v, d_v, ten%cg, h)
            end if
            if (stat%code /= STATUS_OK) return
            call check_rig(i, h)
            if (stat%code /= STATUS_OK) return
            ! the attitude at rest: gravity in the body frame, or the roll about CD
            if (have_g) then
                g_v = [ct%v(i, 'gx', 0.0_dp), ct%v(i, 'gy', 0.0_dp), ct%v(i, 'gz', 0.0_dp)]
                call ct%check_value(stat, i, 'gx', norm2(g_v), norm2(g_v) > 1.0e-300_dp .and. &
                    dot_product(g_v, h%up) < 0.0_dp, 'gx, gy, gz the direction of gravity in '// &
                    'the body frame at rest (any length but 0), within 90 deg of -up')
                if (stat%code /= STATUS_OK) return
                h%attitude = .true.
                h%gravity = g_v/norm2(g_v)
            else if (ct%has('tilt')) then
                tl = ct%v(i, 'tilt', 0.0_dp)
                call ct%check_value(stat, i, 'tilt', tl, abs(tl) < 45.0_dp, '|tilt| < 45 '// &
                    '(degrees: the roll about CD at rest; gravity in the body frame is -cos '// &
                    'tilt up + sin tilt (up x along))')
                if (stat%code /= STATUS_OK) return
                h%attitude = .true.
                h%gravity = -cos(tl*deg)*h%up + sin(tl*deg)*cross(h%up, h%along)
            end if
            ! the timing
            associate (o => m%obs(i))
                o%kind = OBS_HANG
                o%line = ct%line(i)
                o%cycles = ct%v(i, 'cycles', 1.0_dp)
                call ct%check_value(stat, i, 'cycles', o%cycles, o%cycles >= 1.0_dp .and. &
                    o%cycles <= 1.0e6_dp, '1 <= cycles <= 1e6 (cycles timed by the period '// &
                    'column)')
                if (stat%code /= STATUS_OK) return
                per = ct%v(i, 'period', 0.0_dp)
                call ct%check_value(stat, i, 'period', per, per > 0.0_dp .and. &
                    per < 1.0e9_dp, '0 < period < 1e9 (s, the time of cycles cycles)')
                if (stat%code /= STATUS_OK) return
                ! a cycle far shorter than the rig's own time scale: no body swings so fast
                ! on it (its radius of gyration would be below 1/2000 of b b'), a period in
                ! other units than s
                t_rig = 2.0_dp*pi*sqrt(min(h%l, h%l_prime)/sus%g)
                if (per/o%cycles < PERIOD_MIN_RIG*t_rig) then
                    call ct%bad_value(stat, i, 'period', rshort(per), 'a cycle (period/'// &
                        'cycles, here '//sci(per/o%cycles, 3)//' s) of at least '// &
                        rshort(PERIOD_MIN_RIG)//' of this hang''s pendulum time 2 pi '// &
                        'sqrt(l/g) = '//sci(t_rig, 3)//' s: no body swings faster on it; '// &
                        'likely: a period in ms or us, not s, or another column')
                    return
                end if
                o%amplitude = ct%v(i, 'amplitude', 0.0_dp)
                call ct%check_value(stat, i, 'amplitude', o%amplitude, o%amplitude >= &
                    0.0_dp .and. o%amplitude < AMPLITUDE_MAX, '0 <= amplitude < '// &
                    rshort(AMPLITUDE_MAX)//' (degrees of theta4; 0: small amplitude)')
                if (stat%code /= STATUS_OK) return
                u_tot = ct%v(i, 'u_period', ten%u(7))
                call ct%check_value(stat, i, 'u_period', u_tot, u_tot >= 0.0_dp .and. &
                    u_tot < per, '0 <= u_period < period (s, of the period column)')
                if (stat%code /= STATUS_OK) return
                call set_timing(o, per, o%cycles, o%amplitude, u_tot)
            end associate
            ! the hang: a new one, or the same pose as its earlier rows
            k = 0
            if (nh > 0) k = findloc(ids(1:nh), h%id, 1)
            if (k == 0) then
                nh = nh + 1
                ids(nh) = h%id
                hangs(nh) = h
                k = nh
            else if (.not. same_hang(hangs(k), h)) then
                call ct%fail_row(stat, i, 'hang '//itoa(h%id)//' has another orientation or '// &
                    'rig than on line '//itoa(hangs(k)%line)//'; allowed: rows of one hang '// &
                    'repeat its timing with the same up, along (or c, d), rig and attitude columns')
                return
            end if
            m%obs(i)%release = k
        end do
        allocate (m%releases(nh))
        do k = 1, nh
            associate (r => m%releases(k), hh => hangs(k))
                r%hang = hh
                r%label = itoa(hh%id)
                r%id = hh%id
                r%line = hh%line
                r%own(1:4) = hh%own
                r%rig%l = hh%l
                r%rig%l_prime = hh%l_prime
                r%rig%b = hh%b
                r%rig%b_prime = hh%b_prime
                r%rig%mass = bod%mass
                r%rig%g = sus%g
                r%estimate = 'I1'
                r%session = ''
            end associate
        end do

    contains

        !> 'up_x' ... the k-th component's column of a vector.
        pure function vec_name(v, k) result(s)
            character(len=*), intent(in) :: v
            integer, intent(in) :: k
            character(len=8) :: s
            s = v//'_'//'xyz'(k:k)
        end function vec_name

        !> up and along of a row: up not 0, along not parallel to it.
        subroutine orientation(i, up, along, hh)
            integer, intent(in) :: i
            real(dp), intent(in) :: up(3), along(3)
            type(hang_t), intent(inout) :: hh
            real(dp) :: nu, a(3), na
            nu = norm2(up)
            if (.not. (nu > 1.0e-300_dp)) then
                call ct%fail_row(stat, i, 'up = '//rlist_short(up)//' is the zero vector; '// &
                    'allowed: the body-frame direction that points up at rest (any length '// &
                    'but 0)')
                return
            end if
            hh%up = up/nu
            a = along - dot_product(along, hh%up)*hh%up
            na = norm2(a)
            if (.not. (na > PARALLEL_TOL*norm2(along)) .or. .not. (na > 0.0_dp)) then
                call ct%fail_row(stat, i, 'along = '//rlist_short(along)//' is 0 or '// &
                    'parallel to up = '//rlist_short(up)//'; allowed: the body-frame '// &
                    'direction from C toward D, not along up')
                return
            end if
            hh%along = a/na
        end subroutine orientation

        !> up, along, b_prime, cg_depth, cg_offset from the points C, D and the mass centre.
        subroutine from_points(i, c, dd, cg, hh)
            integer, intent(in) :: i
            real(dp), intent(in) :: c(3), dd(3), cg(3)
            type(hang_t), intent(inout) :: hh
            real(dp) :: a(3), bp, s, p(3), depth
            a = dd - c
            bp = norm2(a)
            if (.not. (bp > 1.0e-12_dp*max(norm2(c), norm2(dd), norm2(cg)))) then
                call ct%fail_row(stat, i, 'D = '//rlist_short(dd)//' is C = '// &
                    rlist_short(c)//'; allowed: two distinct attachment points')
                return
            end if
            hh%along = a/bp
            s = dot_product(cg - c, hh%along)
            p = (cg - c) - s*hh%along
            depth = norm2(p)
            if (.not. (depth > 1.0e-6_dp*bp)) then
                call ct%fail_row(stat, i, '&tensor cg = '//rlist_short(cg)//' lies on the '// &
                    'line CD; allowed: a mass centre off the line through the attachment '// &
                    'points (it hangs below it)')
                return
            end if
            hh%up = -p/depth
            hh%b_prime = bp
            hh%own(4) = .true.          ! the spacing of this hang's own attachment points
            hh%cg_depth = depth
            hh%cg_offset = s - 0.5_dp*bp
        end subroutine from_points

        !> A hang's rig in range: lengths > 0 over b_prime in RATIO_MIN .. RATIO_MAX, the
        !! mass centre below CD.
        !> A platform's table: hangs by up/along (the body's direction normal to the
        !! platform and its x axis), the platform's geometry the deck's except l.
        subroutine platform_columns()
            character(len=7), parameter :: NOT_PL(3) = ['l_prime', 'b      ', 'b_prime']
            character(len=:), allocatable :: w
            integer :: j
            if (form_pts) then
                call ct%fail(stat, 'the attachment points c_x ... d_z on a platform of '// &
                    itoa(sus%cables)//' cables; allowed: up_x, up_y, up_z (the body''s '// &
                    'direction normal to the platform) and along_x, along_y, along_z (the '// &
                    'body''s direction along the platform''s x axis)')
                return
            end if
            do j = 1, 3
                w = trim(NOT_PL(j))
                if (.not. ct%has(trim(w))) cycle
                call ct%fail(stat, 'column '//quoted(trim(w))//' on a platform of '// &
                    itoa(sus%cables)//' cables; allowed: the platform''s radius and '// &
                    'radius_prime in &suspension, a column l (every cable''s length)')
                return
            end do
        end subroutine platform_columns

        subroutine check_rig(i, hh)
            integer, intent(in) :: i
            type(hang_t), intent(in) :: hh
            real(dp) :: v(4)
            integer :: j
            v = [hh%l, hh%l_prime, hh%b, hh%b_prime]
            do j = 1, 4
                if (.not. (v(j) > 0.0_dp .and. v(j) < 1.0e100_dp)) then
                    call ct%fail_row(stat, i, trim(RIG_COLUMNS(j))//' = '//rshort(v(j))// &
                        ' out of range; allowed: 0 < '//trim(RIG_COLUMNS(j))//' < 1e100 '// &
                        '(deck units)')
                    return
                end if
            end do
            do j = 1, 3
                if (.not. (v(j)/v(4) >= RATIO_MIN .and. v(j)/v(4) <= RATIO_MAX)) then
                    call ct%fail_row(stat, i, trim(RIG_COLUMNS(j))//'/b_prime = '// &
                        rshort(v(j)/v(4))//' out of range; allowed: '//rshort(RATIO_MIN)// &
                        ' <= '//trim(RIG_COLUMNS(j))//'/b_prime <= '//rshort(RATIO_MAX))
                    return
                end if
            end do
            if (hh%cables > 2) then
                ! on a platform the body may rest above the attachments (the platform
                ! model judges whether it hangs stably)
                if (.not. (abs(hh%cg_depth) <= RATIO_MAX*hh%b_prime .and. &
                           abs(hh%cg_offset_y) <= RATIO_MAX*hh%b_prime)) then
                    call ct%fail_row(stat, i, 'cg_depth, cg_offset_y = '// &
                        rshort(hh%cg_depth)//', '//rshort(hh%cg_offset_y)//' out of range; '// &
                        'allowed: |cg_depth|, |cg_offset_y| <= '//rshort(RATIO_MAX)// &
                        ' b_prime (2 radius_prime)')
                    return
                end if
            else if (.not. (hh%cg_depth > 1.0e-6_dp*hh%b_prime .and. &
                       hh%cg_depth <= RATIO_MAX*hh%b_prime)) then
                call ct%fail_row(stat, i, 'cg_depth = '//rshort(hh%cg_depth)//': the mass '// &
                    'centre must hang below the line CD; allowed: 1e-6 b_prime < cg_depth '// &
                    '<= '//rshort(RATIO_MAX)//' b_prime')
                return
            end if
            if (.not. (abs(hh%cg_offset) <= RATIO_MAX*hh%b_prime)) then
                call ct%fail_row(stat, i, 'cg_offset = '//rshort(hh%cg_offset)//' out of '// &
                    'range; allowed: |cg_offset| <= '//rshort(RATIO_MAX)//' b_prime')
                return
            end if
        end subroutine check_rig

    end subroutine read_hangs

    !> Two rows describe one hang: the same orientation and rig (to roundoff).
    pure logical function same_hang(a, b)
        type(hang_t), intent(in) :: a, b
        real(dp), parameter :: TOL = 1.0e-12_dp
        same_hang = all(abs(a%up - b%up) <= TOL) .and. all(abs(a%along - b%along) <= TOL) &
            .and. near(a%l, b%l) .and. near(a%l_prime, b%l_prime) .and. near(a%b, b%b) .and. &
            near(a%b_prime, b%b_prime) .and. abs(a%cg_depth - b%cg_depth) <= TOL*a%b_prime &
            .and. abs(a%cg_offset - b%cg_offset) <= TOL*a%b_prime .and. &
            abs(a%cg_offset_y - b%cg_offset_y) <= TOL*a%b_prime .and. &
            (a%attitude .eqv. b%attitude) .and. all(abs(a%gravity - b%gravity) <= TOL)
    contains
        pure logical function near(x, y)
            real(dp), intent(in) :: x, y
            near = abs(x - y) <= TOL*abs(x)
        end function near
    end function same_hang

end module measurement_read
