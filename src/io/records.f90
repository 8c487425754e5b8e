!> Records of a swing as instruments write them: time and a measured value (and, when
!! given, each sample's standard uncertainty), read and checked whole before any computing
!! (read_record_file), with the record's mean period from its crossings (mean_period).
!!
!! A record is a table (module tables: blanks, tabs, commas or semicolons between fields,
!! CR LF line ends, a UTF-8 byte order mark, header lines before the numbers, '#'
!! comments).  &measurement record_columns picks the columns of time (s), value and,
!! optionally, each sample's standard uncertainty (1-based; default 1, 2); record_units
!! says what the value is: 'rad' or 'deg' (theta4) or 'rad/s' or 'deg/s' (W = omega . n3);
!! without it &measurement quantity says angle (rad) or rate (rad/s).  Values in degrees
!! are turned into radians here: a record_t is always in rad or rad/s.  Times need not
!! count from the release (the fit finds it).
module records
    use kinds, only: dp, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, sci
    use tables, only: table_t, read_table
    implicit none
    private

    !> A record: time (s), the measured value (rad or rad/s) and, when the record gives it,
    !! each sample's standard uncertainty (else 1).
    type, public :: record_t
        real(dp), allocatable :: t(:), v(:), u(:)
        logical :: has_u = .false.
        logical :: rate = .false.               !! W (rad/s), else theta4 (rad)
        real(dp) :: to_rad = 1.0_dp             !! the file's unit in rad (or rad/s)
    end type record_t

    !> How a record file is to be read: its columns, its unit, the rig's rate scale.
    type, public :: record_format_t
        !> time, value, u (0: none; -1: column 3 when the file has exactly three columns)
        integer :: columns(3) = [1, 2, -1]
        logical :: rate = .false.               !! a rate (W), else an angle (theta4)
        real(dp) :: to_rad = 1.0_dp             !! the value's unit in rad (deg: pi/180)
        character(len=8) :: units = 'rad'       !! for messages
        real(dp) :: rate_scale = 1.0_dp         !! sqrt(g/b'): rad/s per rad per unit tau
    end type record_format_t

    public :: read_record_file, record_format, mean_period

    integer, parameter, public :: MIN_SAMPLES = 20          !! shortest record
    integer, parameter, public :: MAX_SAMPLES = 2000000     !! longest record
    !> Largest recorded value: rad (angle) or rad per unit of tau (rate, W/sqrt(g/b')); a
    !! standard uncertainty from U_MIN to VALUE_MAX in the same units (a smaller one makes
    !! weights 1/u that overflow the fit's sum of squares).
    real(dp), parameter, public :: VALUE_MAX = 1.0e3_dp, U_MIN = 1.0e-12_dp

contains

    !> How a deck's records are to be read (&measurement record_columns, record_units or
    !! quantity; the rig's sqrt(g/b') for the range of a rate).
    pure function record_format(columns, quantity, record_units, g, b_prime) result(f)
        integer, intent(in) :: columns(3)               !! &measurement record_columns
        character(len=*), intent(in) :: quantity        !! 'angle' or 'rate'
        character(len=*), intent(in) :: record_units    !! RECORD_UNITS_ALLOWED or ''
        real(dp), intent(in) :: g, b_prime              !! the rig's
        type(record_format_t) :: f
        f%columns = columns
        f%rate = trim(quantity) == 'rate'
        f%units = trim(merge('rad/s', 'rad  ', f%rate))
        f%to_rad = 1.0_dp
        if (len_trim(record_units) > 0) then
            f%units = trim(record_units)
            if (index(record_units, 'deg') == 1) f%to_rad = deg
        end if
        f%rate_scale = sqrt(g/b_prime)
    end function record_format

    !> Read and check a record file: its table (module tables), the columns of the format;
    !! time (s) strictly increasing; the value within VALUE_MAX rad (or VALUE_MAX sqrt(g/b')
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
        real(dp) :: vmax, x
        integer :: n, i, need, cols(3)
        character(len=:), allocatable :: per_tau, raw
        if (present(bytes)) then
            ! through a local: gfortran 12 hands an optional deferred-length dummy on to
            ! another with a copy of its length, and the length read is lost
            call read_table(path, tab, stat, MAX_SAMPLES, bytes=raw)
            if (allocated(raw)) call move_alloc(raw, bytes)
        else
            call read_table(path, tab, stat, MAX_SAMPLES)
        end if
        if (stat%code /= STATUS_OK) then
            if (index(stat%msg, 'more than') == 1) stat%msg = stat%msg(1:index(stat%msg, &
                ' rows;') - 1)//' samples; allowed: at most '//itoa(MAX_SAMPLES)
            return
        end if
        cols = f%columns
        if (cols(3) < 0) cols(3) = merge(3, 0, tab%ncol == 3)
        need = maxval(cols)
        if (tab%ncol < need) then
            call set_error(stat, ERR_DECK, itoa(tab%ncol)//' columns (line '// &
                itoa(tab%line(1))//'), record_columns asks for column '//itoa(need)// &
                '; allowed: record_columns = T, V or T, V, U naming columns of the file')
            return
        end if
        n = tab%nrow
        if (n < MIN_SAMPLES) then
            call set_error(stat, ERR_DECK, itoa(n)//' samples; allowed: at least '// &
                itoa(MIN_SAMPLES))
            return
        end if
        rec%rate = f%rate
        rec%to_rad = f%to_rad
        rec%t = tab%v(:, cols(1))
        rec%v = tab%v(:, cols(2))*f%to_rad
        rec%has_u = cols(3) > 0
        if (rec%has_u) then
            rec%u = tab%v(:, cols(3))*f%to_rad
        else
            allocate (rec%u(n))
            rec%u = 1.0_dp
        end if
        vmax = VALUE_MAX
        per_tau = ''
        if (f%rate) then
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
            if (abs(rec%v(i)) > vmax) then
                x = rec%v(i)/f%to_rad
                call set_error(stat, ERR_DECK, 'line '//itoa(tab%line(i))//': value '// &
                    sci(x)//' '//trim(f%units)//' is too large; allowed: |value| <= '// &
                    sci(vmax)//trim(merge(' rad/s', ' rad  ', f%rate))//per_tau// &
                    trim(unit_hint(f))//'')
                return
            end if
            if (rec%has_u) then
                if (.not. (rec%u(i) >= U_MIN*merge(f%rate_scale, 1.0_dp, f%rate) .and. &
                           rec%u(i) <= vmax)) then
                    call set_error(stat, ERR_DECK, 'line '//itoa(tab%line(i))//': standard '// &
                        'uncertainty '//sci(rec%u(i)/f%to_rad)//' '//trim(f%units)//' is out '// &
                        'of range; allowed: from '//sci(U_MIN*merge(f%rate_scale, 1.0_dp, &
                        f%rate))//' to '//sci(vmax)//trim(merge(' rad/s', ' rad  ', f%rate)))
                    return
                end if
            end if
        end do
    end subroutine read_record_file

    !> A hint on the units for a value too large: a record in degrees read as radians.
    pure function unit_hint(f) result(s)
        type(record_format_t), intent(in) :: f
        character(len=:), allocatable :: s
        s = ''
        if (f%to_rad == 1.0_dp) s = '; a record in degrees needs record_units = '''// &
            trim(merge('deg/s', 'deg  ', f%rate))//''''
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

end module records
