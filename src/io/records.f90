!> Records of a swing as instruments and video trackers write them: time and a measured
!! value (and, when asked for, each sample's standard uncertainty), read and checked whole
!! before any computing (read_record_file), with the record's mean period from its
!! crossings (mean_period).
!!
!! A record is a table (module tables: blanks, tabs, commas or semicolons between fields,
!! CR LF line ends, a UTF-8 byte order mark, header lines before the numbers, '#'
!! comments).  &measurement record_columns picks the columns of time, value and,
!! optionally, each sample's standard uncertainty, by number (1-based) or by their names in
!! the header; only those columns must be numbers, the others may hold anything.  Without
!! record_columns: columns 1 and 2, or, in a gyro export whose header names its axes
!! ('Gyroscope x (rad/s)', 'gyro.y', ...), the time and the axis with the largest swing;
!! a third column is a sample's u only when record_columns names it.  The time is in s,
!! in ms when its column's name says so ('t (ms)'); with record_frame_rate F the time
!! column holds frame numbers (t = frame/F) or, without a time column, t = (row - 1)/F.
!! The value's unit: record_units, or its column's name ('(deg/s)'), which must agree;
!! else &measurement quantity: angle (rad) or rate (rad/s).  'rad' or 'deg' (theta4),
!! 'rad/s' or 'deg/s' (W = omega . n3).  Values in degrees are turned into radians here:
!! a record_t is always in rad or rad/s.  Times need not count from the release (the fit
!! finds it when t0 is estimated).  Quantity 'rates': record_columns T, X, Y, Z (or a gyro
!! export's three axes, or columns 1 .. 4), the instrument's three rates into vs and the
!! rate about the vertical they give into v (record_format_t's down).  Quantity 'point' (a
!! video's track of a point of the body): record_columns T, X, Y (or columns 1 .. 3, or a
!! header's two axes 'pos x', 'pos y'), the two coordinates into vs and the one with the
!! larger swing into v, in the track's units (px, record_scale m/px), or in m, cm or mm
!! when the columns' names say so (turned into m here; record_scale then 1); the two
!! columns' units must agree.
module records
    use kinds, only: dp, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, sci, quoted, clip
    use tables, only: table_t, column_name_t, load_table_file, read_picked, header_fields, &
        name_unit, name_base
    implicit none
    private

    !> A record: time (s), the measured value (rad or rad/s) and, when the record gives it,
    !! each sample's standard uncertainty (else 1).
    type, public :: record_t
        real(dp), allocatable :: t(:), v(:), u(:)
        !> quantity 'rates': the instrument's three rates (rad/s), three blocks of the n
        !! samples, axis k's sample i at (k - 1) n + i (v then holds the rate about the
        !! vertical they give, record_fit's vertical_of_rates)
        real(dp), allocatable :: vs(:)
        logical :: has_u = .false.
        logical :: rate = .false.               !! W (rad/s), else theta4 (rad)
        real(dp) :: to_rad = 1.0_dp             !! the file's unit in rad (or rad/s)
        character(len=8) :: units = 'rad'       !! the file's unit: rad, deg, rad/s, deg/s
        !> the unit was stated (record_units, or the value column's name), not assumed
        logical :: units_stated = .false.
        !> the value's column as the file's header names it ('' without one)
        character(len=256) :: value_name = ''
        !> the value is the axis with the largest swing of a gyro export (no record_columns)
        logical :: axis_chosen = .false.
        !> one line for the run's notes ('' for none): a column left unused
        character(len=256) :: note = ''
    end type record_t

    !> How a record file is to be read: its columns, its unit, the rig's rate scale.
    type, public :: record_format_t
        !> time, value, u: 1-based columns; 0: none (the time: from the row and frame_rate)
        !! or by name (names); -1 in the third: record_columns not given
        integer :: columns(4) = [1, 2, -1, -1]
        character(len=256) :: names(4) = ''     !! by name (lower case) where columns is 0
        !> quantity 'rates': three value columns, the instrument's x, y, z (columns 2 .. 4,
        !! or a gyro export's three axes), read into record_t%vs
        logical :: rates = .false.
        !> quantity 'rates': the body's axis b_1 (down at rest) in the instrument's axes; the
        !! record's v is the rate about the vertical they give, W = -(down . rates)
        real(dp) :: down(3) = [1.0_dp, 0.0_dp, 0.0_dp]
        !> quantity 'point': two value columns, the point's coordinates X, Y (columns 2, 3,
        !! or a header's two axes), read into record_t%vs in the track's units
        logical :: point = .false.
        !> quantity 'point': record_scale, the length of one unit of the track (m)
        real(dp) :: scale = 1.0_dp
        real(dp) :: frame_rate = 0.0_dp         !! frames a second (0: the time is in s)
        logical :: rate = .false.               !! a rate (W), else an angle (theta4)
        real(dp) :: to_rad = 1.0_dp             !! the value's unit in rad (deg: pi/180)
        character(len=8) :: units = 'rad'       !! for messages
        logical :: units_given = .false.        !! record_units given
        logical :: quantity_given = .false.     !! quantity given
        real(dp) :: rate_scale = 1.0_dp         !! sqrt(g/b'): rad/s per rad per unit tau
    end type record_format_t

    public :: read_record_file, record_format, mean_period, column_unit, clean_mean_period, &
              u_column_warning, median_value, chosen_axis_note

    integer, parameter, public :: MIN_SAMPLES = 20          !! shortest record
    integer, parameter, public :: MAX_SAMPLES = 2000000     !! longest record
    !> Largest recorded value: rad (angle) or rad per unit of tau (rate, W/sqrt(g/b')); a
    !! standard uncertainty from U_MIN to VALUE_MAX in the same units (a smaller one makes
    !! weights 1/u that overflow the fit's sum of squares).
    real(dp), parameter, public :: VALUE_MAX = 1.0e3_dp, U_MIN = 1.0e-12_dp
    !> Largest coordinate of a track (quantity 'point'), in its units (px or m)
    real(dp), parameter, public :: TRACK_MAX = 1.0e9_dp
    !> A sample further from the fitted model than this many robust scales of the
    !! residuals is no part of the swing (a dropout, a spike; Huber's weight below 0.27).
    real(dp), parameter, public :: OUTLIER_SCALES = 5.0_dp
    !> Stated u and residuals that differ by more than this factor disagree.
    real(dp), parameter :: STATED_U_FACTOR = 3.0_dp

contains

    !> How a deck's records are to be read (&measurement record_columns, record_units or
    !! quantity, record_frame_rate; the rig's sqrt(g/b') for the range of a rate).
    pure function record_format(columns, quantity, record_units, g, b_prime, names, &
                                frame_rate, quantity_given) result(f)
        integer, intent(in) :: columns(4)               !! &measurement record_columns
        character(len=*), intent(in) :: quantity        !! 'angle' or 'rate'
        character(len=*), intent(in) :: record_units    !! RECORD_UNITS_ALLOWED or ''
        real(dp), intent(in) :: g, b_prime              !! the rig's
        character(len=*), intent(in), optional :: names(4)  !! record_columns by name
        real(dp), intent(in), optional :: frame_rate    !! record_frame_rate
        logical, intent(in), optional :: quantity_given !! quantity given by the deck
        type(record_format_t) :: f
        f%columns = columns
        if (present(names)) f%names = names
        if (present(frame_rate)) f%frame_rate = frame_rate
        if (present(quantity_given)) f%quantity_given = quantity_given
        f%rates = trim(quantity) == 'rates'
        f%point = trim(quantity) == 'point'
        f%rate = trim(quantity) == 'rate' .or. f%rates
        f%units = trim(merge('rad/s', 'rad  ', f%rate))
        f%to_rad = 1.0_dp
        if (len_trim(record_units) > 0) then
            f%units = trim(record_units)
            f%units_given = .true.
            if (index(record_units, 'deg') == 1) f%to_rad = deg
        end if
        f%rate_scale = sqrt(g/b_prime)
    end function record_format

    !> Read and check a record file: its table (module tables) and the columns of the
    !! format (record_columns; without it 1, 2 or a gyro export's axis with the largest
    !! swing); the time in s (ms or frames as the column's name or record_frame_rate
    !! say), strictly increasing; the unit of the value from record_units or its column's
    !! name (a conflict refused), the value within VALUE_MAX rad (or VALUE_MAX sqrt(g/b')
    !! rad/s for a rate) after conversion to rad; a sample's u from U_MIN to VALUE_MAX in
    !! those units; MIN_SAMPLES .. MAX_SAMPLES samples.  ERR_DECK naming the line.
    subroutine read_record_file(path, f, rec, stat, bytes)
        character(len=*), intent(in) :: path    !! the file
        type(record_format_t), intent(in) :: f  !! its columns and units
        type(record_t), intent(out) :: rec
        type(status_t), intent(out) :: stat     !! ERR_DECK
        !> the file's bytes as read once (for its CRC-64), when asked
        character(len=:), allocatable, intent(out), optional :: bytes
        type(table_t) :: tab
        type(column_name_t), allocatable :: head(:)
        real(dp) :: vmax, x, tscale, to_rad
        integer :: n, i, kt, kv, ku, k, np, kr(3), o, nval
        integer, allocatable :: at(:), axes(:)
        character(len=256), allocatable :: nm(:)
        character(len=:), allocatable :: per_tau, text, tname, vname, tunit, vunit, units
        logical :: named, rate
        stat%code = STATUS_OK
        call load_table_file(path, text, stat)
        if (stat%code /= STATUS_OK) return
        ! the columns asked for: record_columns, else 1, 2 or the axes of a gyro export
        allocate (axes(0))
        kr = 0
        if (f%columns(3) == -1) then
            call header_fields(text, head, named)
            if (named) call gyro_axes(head, axes)
        end if
        kt = 0
        kv = 0
        ku = 0
        allocate (at(0), nm(0))
        nval = merge(2, 3, f%point)
        if (f%rates .or. f%point) then
            ! time and the instrument's x, y, z (a track's x, y): record_columns, or a gyro
            ! export's (a track's header's) axes
            if (size(axes) == nval) then
                kt = add(time_column(head, axes), '')
                do k = 1, nval
                    kr(k) = add(axes(k), '')
                end do
            else if (f%columns(3) == -1) then
                kt = add(1, '')
                do k = 1, nval
                    kr(k) = add(k + 1, '')
                end do
            else
                if (f%columns(1) > 0 .or. len_trim(f%names(1)) > 0) kt = add(f%columns(1), &
                                                                              f%names(1))
                do k = 1, nval
                    kr(k) = add(f%columns(k + 1), f%names(k + 1))
                end do
            end if
            kv = kr(1)
            deallocate (axes)
            allocate (axes(0))
        else if (size(axes) > 0) then
            kt = add(time_column(head, axes), '')
            do k = 1, size(axes)
                i = add(axes(k), '')
            end do
        else if (f%columns(3) == -1) then
            kt = add(1, '')
            kv = add(2, '')
        else
            if (f%columns(1) > 0 .or. len_trim(f%names(1)) > 0) kt = add(f%columns(1), &
                                                                          f%names(1))
            kv = add(f%columns(2), f%names(2))
            if (f%columns(3) > 0 .or. len_trim(f%names(3)) > 0) ku = add(f%columns(3), &
                                                                          f%names(3))
        end if
        np = size(at)
        call read_picked(text, tab, stat, MAX_SAMPLES, at, nm, 'record_columns')
        if (present(bytes)) call move_alloc(text, bytes)
        if (stat%code /= STATUS_OK) then
            if (index(stat%msg, 'more than') == 1) stat%msg = stat%msg(1:index(stat%msg, &
                ' rows;') - 1)//' samples; allowed: at most '//itoa(MAX_SAMPLES)
            if (index(stat%msg, 'asks for column') > 0) stat%msg = stat%msg(1:index(stat%msg, &
                '; allowed') - 1)//'; allowed: record_columns = '//trim(merge('T, X, Y        ', &
                'T, V or T, V, U', f%point))//' naming columns of the file'
            if (index(stat%msg, 'asks for column') > 0 .and. f%point) stat%msg = &
                trim(stat%msg)//' (quantity = ''point'': the time and the point''s two '// &
                'coordinates)'
            return
        end if
        n = tab%nrow
        if (n < MIN_SAMPLES) then
            call set_error(stat, ERR_DECK, itoa(n)//' samples; allowed: at least '// &
                itoa(MIN_SAMPLES))
            return
        end if
        if (size(axes) > 0) then
            ! the axis with the largest swing (the robust spread of its values)
            kv = 2
            x = -1.0_dp
            do k = 2, np
                if (spread_of(tab%v(:, k)) > x) then
                    x = spread_of(tab%v(:, k))
                    kv = k
                end if
            end do
            rec%axis_chosen = .true.
        end if
        tname = column_name(kt)
        vname = column_name(kv)
        rec%value_name = vname
        if (f%columns(3) == -1 .and. size(axes) == 0 .and. tab%ncol == 3 .and. .not. &
            f%point) rec%note = &
            'its column 3 is not used (record_columns = 1, 2, 3 takes it as each sample''s '// &
            'standard uncertainty)'
        ! the time: s, or ms by its name, or frames
        tunit = ''
        if (kt > 0) tunit = column_unit(tname)
        tscale = 1.0_dp
        if (kt > 0) then
            if (f%frame_rate > 0.0_dp) then
                if (tunit == 's' .or. tunit == 'ms') then
                    call set_error(stat, ERR_DECK, 'the time column '//col_id(kt)//' is in '// &
                        tunit//', and record_frame_rate = '//sci(f%frame_rate, 4)//' says '// &
                        'it holds frame numbers; allowed: record_frame_rate with a column of '// &
                        'frame numbers (or none), or leave record_frame_rate out')
                    return
                end if
                tscale = 1.0_dp/f%frame_rate
            else if (tunit == 'ms') then
                tscale = 1.0e-3_dp
            else if (len(tunit) > 0 .and. tunit /= 's') then
                call set_error(stat, ERR_DECK, 'the time column '//col_id(kt)//' is in '// &
                    tunit//', not a time; allowed: record_columns naming the time first (s '// &
                    'or ms), then the value')
                return
            else if (index(name_base(tname), 'frame') == 1) then
                call set_error(stat, ERR_DECK, 'the time column '//col_id(kt)//' holds '// &
                    'frame numbers; allowed: record_frame_rate = F (frames a second: t = '// &
                    'frame/F), or a column of times in s')
                return
            end if
        end if
        if (f%point) then
            call read_track()
            return
        end if
        ! the value's unit: record_units, or its column's name, or quantity
        rate = f%rate
        to_rad = f%to_rad
        units = trim(f%units)
        vunit = column_unit(vname)
        if (vunit == 's' .or. vunit == 'ms') then
            call set_error(stat, ERR_DECK, 'the value column '//col_id(kv)//' is in '// &
                vunit//', a time; allowed: record_columns naming the time first, then the value')
            return
        end if
        if (name_base(vname) == 'absolute' .or. name_base(vname) == 'magnitude') then
            call set_error(stat, ERR_DECK, 'the value column '//col_id(kv)//' is the '// &
                'magnitude of the three axes (never negative), not a swing about one axis; '// &
                'allowed: an axis, e.g. record_columns = ''Time (s)'', ''Gyroscope z (rad/s)'' '// &
                '(or record_columns left out: the axis with the largest swing)')
            return
        end if
        if (len(vunit) > 0) then
            if (f%units_given .and. vunit /= trim(f%units)) then
                call set_error(stat, ERR_DECK, 'the value column '//col_id(kv)//' says '// &
                    vunit//', and record_units = '//quoted(trim(f%units))//'; allowed: '// &
                    'record_units as the column''s name says ('//quoted(vunit)//'), or left out')
                return
            end if
            if (f%quantity_given .and. (index(vunit, '/s') > 0 .neqv. f%rate)) then
                call set_error(stat, ERR_DECK, 'the value column '//col_id(kv)//' says '// &
                    vunit//' (a'//trim(merge(' rate  ', 'n angle', index(vunit, '/s') > 0))// &
                    '), and quantity = '//quoted(trim(merge('rate ', 'angle', f%rate)))// &
                    '; allowed: quantity as the column''s unit says, or left out')
                return
            end if
            rate = index(vunit, '/s') > 0
            to_rad = merge(deg, 1.0_dp, index(vunit, 'deg') == 1)
            units = vunit
        end if
        rec%rate = rate
        rec%to_rad = to_rad
        rec%units = units
        rec%units_stated = f%units_given .or. len(vunit) > 0
        if (kt > 0) then
            rec%t = tab%v(:, kt)*tscale
        else
            rec%t = [(real(i - 1, dp)/f%frame_rate, i=1, n)]
        end if
        rec%v = tab%v(:, kv)*to_rad
        if (f%rates) then
            allocate (rec%vs(3*n))
            do o = 1, 3
                if (column_unit(column_name(kr(o))) /= vunit) then
                    call set_error(stat, ERR_DECK, 'the rate columns '//col_id(kr(1))//' and '// &
                        col_id(kr(o))//' state different units; allowed: three columns '// &
                        'of one unit (rad/s or deg/s)')
                    return
                end if
                rec%vs((o - 1)*n + 1:o*n) = tab%v(:, kr(o))*to_rad
            end do
            rec%v = -(f%down(1)*rec%vs(1:n) + f%down(2)*rec%vs(n + 1:2*n) + &
                      f%down(3)*rec%vs(2*n + 1:3*n))
            if (f%quantity_given .and. .not. rate) then
                call set_error(stat, ERR_DECK, 'the rate columns are in '//units//', an '// &
                    'angle, and quantity = ''rates''; allowed: rates in rad/s or deg/s')
                return
            end if
        end if
        rec%has_u = ku > 0
        if (rec%has_u) then
            rec%u = tab%v(:, ku)*to_rad
        else
            allocate (rec%u(n))
            rec%u = 1.0_dp
        end if
        vmax = VALUE_MAX
        per_tau = ''
        if (rate) then
            vmax = VALUE_MAX*f%rate_scale
            per_tau = ' (= '//sci(VALUE_MAX)//' sqrt(g/b_prime))'
        end if
        do i = 1, n
            if (i > 1) then
                if (.not. (rec%t(i) > rec%t(i - 1))) then
                    call set_error(stat, ERR_DECK, 'line '//itoa(tab%line(i))//': time '// &
                        sci(rec%t(i), 6)//' s is not after the previous sample''s '// &
                        sci(rec%t(i - 1), 6)//' s; allowed: time strictly increasing (s)')
                    return
                end if
            end if
            if (f%rates) then
                ! the three rates (v, the vertical one they give, is within sqrt(3) of them)
                x = maxval(abs(rec%vs([i, n + i, 2*n + i])))
                if (x > vmax) rec%v(i) = sign(x, rec%v(i))
            end if
            if (abs(rec%v(i)) > vmax) then
                x = rec%v(i)/to_rad
                call set_error(stat, ERR_DECK, 'line '//itoa(tab%line(i))//': value '// &
                    sci(x)//' '//units//' is too large; allowed: |value| <= '// &
                    sci(vmax)//trim(merge(' rad/s', ' rad  ', rate))//per_tau// &
                    trim(unit_hint(rec))//'')
                return
            end if
            if (rec%has_u) then
                if (.not. (rec%u(i) >= U_MIN*merge(f%rate_scale, 1.0_dp, rate) .and. &
                           rec%u(i) <= vmax)) then
                    call set_error(stat, ERR_DECK, 'line '//itoa(tab%line(i))//': standard '// &
                        'uncertainty '//sci(rec%u(i)/to_rad)//' '//units//' is out '// &
                        'of range; allowed: from '//sci(U_MIN*merge(f%rate_scale, 1.0_dp, &
                        rate))//' to '//sci(vmax)//trim(merge(' rad/s', ' rad  ', rate)))
                    return
                end if
            end if
        end do
    contains
        !> quantity 'point': the track's two coordinates into rec%vs (rec%v the one with the
        !! larger swing), in
        !! px (or the units the columns' names state, the same for both: m, cm or mm, turned
        !! into m, with record_scale 1), each within TRACK_MAX; the time strictly increasing.
        subroutine read_track()
            character(len=:), allocatable :: ux, uy
            real(dp) :: to_m
            if (f%units_given) then
                call set_error(stat, ERR_DECK, 'record_units = '//quoted(trim(f%units))// &
                    ' with quantity = ''point''; allowed: record_units left out (a track''s '// &
                    'columns are in px, by record_scale in m, or in m, cm or mm as their '// &
                    'names say)')
                return
            end if
            do o = 1, 2
                ux = column_unit(column_name(kr(o)))
                if (len(ux) > 0) then
                    call set_error(stat, ERR_DECK, 'the coordinate column '//col_id(kr(o))// &
                        ' is in '//ux//', not a length; allowed: record_columns = T, X, Y '// &
                        'naming the time and the point''s two coordinates (px, m, cm or mm)')
                    return
                end if
            end do
            ux = length_unit(column_name(kr(1)))
            uy = length_unit(column_name(kr(2)))
            if (ux /= uy) then
                call set_error(stat, ERR_DECK, 'the coordinate columns '//col_id(kr(1))// &
                    ' and '//col_id(kr(2))//' state different units ('//quoted(ux)//', '// &
                    quoted(uy)//'); allowed: two columns of one unit (px, m, cm or mm)')
                return
            end if
            to_m = 1.0_dp
            if (ux == 'cm') to_m = 1.0e-2_dp
            if (ux == 'mm') to_m = 1.0e-3_dp
            if (len(ux) > 0 .and. ux /= 'px' .and. f%scale /= 1.0_dp) then
                call set_error(stat, ERR_DECK, 'the coordinate columns '//col_id(kr(1))// &
                    ' and '//col_id(kr(2))//' are in '//ux//', a length, and record_scale = '// &
                    sci(f%scale, 4)//' m a unit; allowed: record_scale left out (or 1) for '// &
                    'columns in m, cm or mm, or columns in px with record_scale in m/px')
                return
            end if
            rec%rate = .false.
            rec%to_rad = 1.0_dp
            rec%units = 'px'
            if (len(ux) > 0 .and. ux /= 'px') rec%units = 'm'
            rec%units_stated = len(ux) > 0
            rec%value_name = column_name(kr(1))
            if (kt > 0) then
                rec%t = tab%v(:, kt)*tscale
            else
                rec%t = [(real(i - 1, dp)/f%frame_rate, i=1, n)]
            end if
            allocate (rec%vs(2*n))
            rec%vs(1:n) = tab%v(:, kr(1))*to_m
            rec%vs(n + 1:2*n) = tab%v(:, kr(2))*to_m
            ! the record's value: the coordinate with the larger swing (as the fit takes it,
            ! record_fit), whose holds and period cut a record of several releases
            rec%v = rec%vs(1:n)
            if (maxval(rec%vs(n + 1:2*n)) - minval(rec%vs(n + 1:2*n)) > &
                maxval(rec%vs(1:n)) - minval(rec%vs(1:n))) then
                rec%v = rec%vs(n + 1:2*n)
                rec%value_name = column_name(kr(2))
            end if
            allocate (rec%u(n))
            rec%u = 1.0_dp
            rec%has_u = .false.
            do i = 1, n
                if (i > 1) then
                    if (.not. (rec%t(i) > rec%t(i - 1))) then
                        call set_error(stat, ERR_DECK, 'line '//itoa(tab%line(i))//': time '// &
                            sci(rec%t(i), 6)//' s is not after the previous sample''s '// &
                            sci(rec%t(i - 1), 6)//' s; allowed: time strictly increasing (s)')
                        return
                    end if
                end if
                x = max(abs(rec%vs(i)), abs(rec%vs(n + i)))/to_m
                if (.not. (x <= TRACK_MAX)) then
                    call set_error(stat, ERR_DECK, 'line '//itoa(tab%line(i))//': a '// &
                        'coordinate of '//sci(x)//' '//unit_word()// &
                        ' is too large; allowed: |coordinate| <= '//sci(TRACK_MAX))
                    return
                end if
            end do
        end subroutine read_track
        !> The track's unit as its columns state it (px when they do not).
        function unit_word() result(w)
            character(len=:), allocatable :: w
            w = length_unit(column_name(kr(1)))
            if (len(w) == 0) w = 'px'
        end function unit_word
        !> One more column asked for: its number, or its name; its place among those asked.
        integer function add(col, name)
            integer, intent(in) :: col
            character(len=*), intent(in) :: name
            character(len=256) :: one(1)
            one(1) = name
            at = [at, col]
            nm = [nm, one]
            add = size(at)
        end function add
        !> The header's name of the k-th column asked for ('' without a header).
        function column_name(k) result(s)
            integer, intent(in) :: k
            character(len=:), allocatable :: s
            s = ''
            if (k <= 0) return
            if (.not. allocated(tab%names)) return
            if (tab%pick(k) <= size(tab%names)) s = tab%names(tab%pick(k))%s
        end function column_name
        !> The k-th column asked for, for a message: column 4, 'gyroscope z (rad/s)'.
        function col_id(k) result(s)
            integer, intent(in) :: k
            character(len=:), allocatable :: s
            s = itoa(tab%pick(k))
            if (len(column_name(k)) > 0) s = s//', '//quoted(clip(column_name(k)))//','
        end function col_id
    end subroutine read_record_file

    !> The unit a column's name states, as record_units spells it: 'rad', 'deg', 'rad/s',
    !! 'deg/s' (also from the degree sign, 'degrees', 'dps'), 's' or 'ms' (also 'sec'); ''
    !! for none or another.
    pure function column_unit(name) result(u)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: u
        character(len=*), parameter :: DEGS = char(194)//char(176)    ! the degree sign, UTF-8
        u = name_unit(name)
        if (u == 'rad' .or. u == 'deg' .or. u == 'rad/s' .or. u == 'deg/s' .or. u == 's' .or. &
            u == 'ms') return
        if (u == 'sec') then
            u = 's'
        else if (u == DEGS .or. u == 'degrees') then
            u = 'deg'
        else if (u == DEGS//'/s' .or. u == 'dps' .or. u == 'degrees/s') then
            u = 'deg/s'
        else
            u = ''
        end if
    end function column_unit

    !> The length a column's name states: 'px' (also 'pixel', 'pixels'), 'm', 'cm', 'mm';
    !! '' for none or another.
    pure function length_unit(name) result(u)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: u
        u = name_unit(name)
        if (u == 'pixel' .or. u == 'pixels' .or. u == 'pix') u = 'px'
        if (u /= 'px' .and. u /= 'm' .and. u /= 'cm' .and. u /= 'mm') u = ''
    end function length_unit

    !> The columns of a gyro export's axes: the header's names that differ only in a last
    !! x, y or z after a blank, '.', '_' or '-' ('Gyroscope x (rad/s)', 'gyro.y'), with the
    !! same unit, two or three of them; none when the header has no such group (or two).
    subroutine gyro_axes(head, axes)
        type(column_name_t), intent(in) :: head(:)
        integer, allocatable, intent(out) :: axes(:)
        character(len=:), allocatable :: bk, bj
        integer :: k, j, ngroups
        integer, allocatable :: grp(:)
        allocate (axes(0))
        ngroups = 0
        do k = 1, size(head)
            if (.not. axis_name(head(k)%s)) cycle
            bk = name_base(head(k)%s)
            allocate (grp(0))
            do j = 1, size(head)
                if (.not. axis_name(head(j)%s)) cycle
                bj = name_base(head(j)%s)
                if (bj(1:len(bj) - 1) == bk(1:len(bk) - 1) .and. &
                    name_unit(head(j)%s) == name_unit(head(k)%s)) grp = [grp, j]
            end do
            if (size(grp) >= 2 .and. grp(1) == k) then
                ngroups = ngroups + 1
                axes = grp
            end if
            deallocate (grp)
        end do
        if (ngroups /= 1) then
            deallocate (axes)
            allocate (axes(0))
        end if
    end subroutine gyro_axes

    !> A name whose base ends in x, y or z after a blank, '.', '_' or '-' (an axis).
    pure logical function axis_name(name)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: b
        integer :: n
        b = name_base(name)
        n = len(b)
        axis_name = .false.
        if (n < 3) return
        axis_name = index('xyz', b(n:n)) > 0 .and. index(' ._-', b(n - 1:n - 1)) > 0
    end function axis_name

    !> The time column of a gyro export: the first whose base name is t or starts with
    !! 'time' ('Time (s)', 'timestamp'), else the first column that is not an axis.
    integer function time_column(head, axes) result(k)
        type(column_name_t), intent(in) :: head(:)
        integer, intent(in) :: axes(:)
        character(len=:), allocatable :: b
        integer :: j
        do j = 1, size(head)
            b = name_base(head(j)%s)
            if (b == 't' .or. index(b, 'time') == 1) then
                k = j
                return
            end if
        end do
        do j = 1, size(head)
            if (all(axes /= j)) then
                k = j
                return
            end if
        end do
        k = 1
    end function time_column

    !> The spread of a column: 1.4826 times the median absolute deviation from its median
    !! (a swing's, not a spike's).
    function spread_of(x) result(s)
        real(dp), intent(in) :: x(:)
        real(dp) :: s
        s = 1.4826_dp*median_value(abs(x - median_value(x)))
    end function spread_of

    !> Heap sort in place (ascending; Williams 1964).
    subroutine heap_sort(a)
        real(dp), intent(inout) :: a(:)
        integer :: n, i, last
        real(dp) :: t
        n = size(a)
        do i = n/2, 1, -1
            call sift(i, n)
        end do
        do last = n, 2, -1
            t = a(1)
            a(1) = a(last)
            a(last) = t
            call sift(1, last - 1)
        end do
    contains
        subroutine sift(i0, m)
            integer, intent(in) :: i0, m
            integer :: r, c
            real(dp) :: v
            r = i0
            v = a(r)
            do
                c = 2*r
                if (c > m) exit
                if (c < m) then
                    if (a(c + 1) > a(c)) c = c + 1
                end if
                if (.not. (a(c) > v)) exit
                a(r) = a(c)
                r = c
            end do
            a(r) = v
        end subroutine sift
    end subroutine heap_sort

    !> A hint on the units for a value too large: a record in degrees read as radians.
    pure function unit_hint(rec) result(s)
        type(record_t), intent(in) :: rec
        character(len=:), allocatable :: s
        s = ''
        if (rec%to_rad == 1.0_dp) s = '; a record in degrees needs record_units = '''// &
            trim(merge('deg/s', 'deg  ', rec%rate))//''''
    end function unit_hint

    !> The record's mean period (s): twice the mean spacing of the crossings of its mean
    !! value, up and down (linear interpolation between samples; a crossing counts only
    !! after the signal has been beyond the mean, on the side it leaves, by a tenth of its
    !! largest excursion, so noise does not add crossings).  0 when fewer than two crossings.
    !! From sample i0 on when given.
    function mean_period(rec, i0) result(tp)
        type(record_t), intent(in) :: rec
        integer, intent(in), optional :: i0     !! first sample (default 1)
        real(dp) :: tp
        real(dp) :: mean, band, tc, t_first, t_last, a, b
        integer :: i, nc, side, k0
        tp = 0.0_dp
        k0 = 1
        if (present(i0)) k0 = max(1, i0)
        if (size(rec%v) - k0 < 2) return
        mean = sum(rec%v(k0:))/size(rec%v(k0:))
        band = 0.1_dp*maxval(abs(rec%v(k0:) - mean))
        side = 0                                ! -1 below the band, +1 above, 0 not yet
        nc = 0
        t_first = 0.0_dp
        t_last = 0.0_dp
        do i = k0 + 1, size(rec%v)
            a = rec%v(i - 1) - mean
            b = rec%v(i) - mean
            if (a < -band) side = -1
            if (a > band) side = 1
            if ((side == -1 .and. a < 0.0_dp .and. b >= 0.0_dp) .or. &
                (side == 1 .and. a > 0.0_dp .and. b <= 0.0_dp)) then
                tc = rec%t(i - 1) + (rec%t(i) - rec%t(i - 1))*a/(a - b)
                nc = nc + 1
                if (nc == 1) t_first = tc
                t_last = tc
                side = 0
            end if
        end do
        if (nc >= 2) tp = 2.0_dp*(t_last - t_first)/(nc - 1)
    end function mean_period


    !> The record's mean period (s) from the samples the fit takes as the swing: from
    !! sample i0 on, those within OUTLIER_SCALES robust scales of the fitted model (1.4826
    !! times the median |e|, and at least 5 % of the swing's half range), so that dropouts
    !! and spikes add no crossings (mean_period).  e: measured - model from sample i0 on;
    !! nout: the samples left out.  0 when fewer than two crossings remain.
    function clean_mean_period(rec, i0, e, nout) result(tp)
        type(record_t), intent(in) :: rec
        integer, intent(in) :: i0
        real(dp), intent(in) :: e(:)
        integer, intent(out) :: nout
        real(dp) :: tp
        type(record_t) :: kept
        real(dp) :: thr
        logical, allocatable :: keep(:)
        integer :: m
        m = min(size(e), size(rec%v) - i0 + 1)
        nout = 0
        tp = 0.0_dp
        if (m < 3) return
        thr = max(OUTLIER_SCALES*1.4826_dp*median_value(abs(e(1:m))), &
                  0.025_dp*(maxval(rec%v(i0:i0 + m - 1)) - minval(rec%v(i0:i0 + m - 1))))
        keep = abs(e(1:m)) <= thr
        nout = count(.not. keep)
        if (nout == 0) then
            tp = mean_period(rec, i0)
            return
        end if
        kept%t = pack(rec%t(i0:i0 + m - 1), keep)
        kept%v = pack(rec%v(i0:i0 + m - 1), keep)
        tp = mean_period(kept)
    end function clean_mean_period

    !> A record's column U (each sample's standard uncertainty) against the fit: one line
    !! ('' when none) when its values are not small against the record's (a median u above
    !! a fifth of the swing's half range), when the residuals scatter STATED_U_FACTOR times
    !! more or less than it says (the rms of residual/u), or when they do not grow with it
    !! (the third of the samples with the largest u against that with the smallest: u
    !! STATED_U_FACTOR times larger, the residuals not even half that).  e: measured -
    !! model from sample i0 on; units: the record's, for the message.
    function u_column_warning(rec, i0, e) result(msg)
        type(record_t), intent(in) :: rec
        integer, intent(in) :: i0
        real(dp), intent(in) :: e(:)
        character(len=:), allocatable :: msg
        real(dp), allocatable :: u(:), us(:)
        real(dp) :: half, um, z, lo, hi, ulo, uhi, rlo, rhi
        integer :: m
        msg = ''
        if (.not. rec%has_u) return
        m = min(size(e), size(rec%u) - i0 + 1)
        if (m < 6) return
        u = rec%u(i0:i0 + m - 1)
        half = 0.5_dp*(maxval(rec%v(i0:i0 + m - 1)) - minval(rec%v(i0:i0 + m - 1)))
        um = median_value(u)
        if (um > 0.2_dp*half) then
            msg = 'identify: the record''s column U (each sample''s standard uncertainty) '// &
                'has a median of '//sci(um/rec%to_rad, 3)//' '//trim(rec%units)//', '// &
                'not small against its swing of +-'//sci(half/rec%to_rad, 3)//' '// &
                trim(rec%units)//': is it a u (or a temperature, a sample number)? u_I1 '// &
                'takes it; name two columns in record_columns to leave it out'
            return
        end if
        z = sqrt(sum((e(1:m)/u)**2)/m)
        if (z > STATED_U_FACTOR .or. z < 1.0_dp/STATED_U_FACTOR) then
            msg = 'identify: the record''s residuals scatter '//sci(z, 2)//' times its '// &
                'column U (each sample''s standard uncertainty): the stated u does not '// &
                'describe the noise; u_I1 takes '//trim(merge('the residuals', 'the stated u ', &
                z > 1.0_dp))//'; name two columns in record_columns to leave U out'
            return
        end if
        ! the thirds of the samples by their u
        us = u
        call heap_sort(us)
        lo = us(max(1, m/3))
        hi = us(min(m, m - m/3 + 1))
        if (.not. (hi > STATED_U_FACTOR*lo)) return
        ulo = sqrt(sum(u**2, mask=u <= lo)/max(1, count(u <= lo)))
        uhi = sqrt(sum(u**2, mask=u >= hi)/max(1, count(u >= hi)))
        rlo = sqrt(sum(e(1:m)**2, mask=u <= lo)/max(1, count(u <= lo)))
        rhi = sqrt(sum(e(1:m)**2, mask=u >= hi)/max(1, count(u >= hi)))
        if (.not. (rhi > 0.5_dp*(uhi/ulo)*rlo)) msg = 'identify: the record''s column U '// &
            '(each sample''s standard uncertainty) is '//sci(uhi/ulo, 2)//' times larger in '// &
            'a third of the samples than in another, their residuals only '// &
            sci(rhi/max(rlo, tiny(1.0_dp)), 2)//' times: the stated u does not scatter as '// &
            'the residuals do; name two columns in record_columns to leave U out'
    end function u_column_warning

    !> For a run's summary line: ', record axis 'NAME' (largest swing)' when the first
    !! record's value is the axis a gyro export was read by (no record_columns), else ''.
    function chosen_axis_note(rec) result(s)
        type(record_t), intent(in) :: rec
        character(len=:), allocatable :: s
        s = ''
        if (rec%axis_chosen) s = ', record axis '//quoted(trim(rec%value_name))// &
            ' (largest swing)'
    end function chosen_axis_note

    !> The median of x (a sorted copy).
    function median_value(x) result(m)
        real(dp), intent(in) :: x(:)
        real(dp) :: m
        real(dp), allocatable :: s(:)
        integer :: n
        n = size(x)
        m = 0.0_dp
        if (n == 0) return
        s = x
        call heap_sort(s)
        m = s((n + 1)/2)
        if (mod(n, 2) == 0) m = 0.5_dp*(s(n/2) + s(n/2 + 1))
    end function median_value

end module records
