!> Records of a swing as instruments write them: time and a measured value (and, when
!! given, each sample's standard uncertainty), read and checked whole before any computing
!! (read_record), with the record's mean period from its crossings (mean_period).
module records
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_DECK
    use text, only: itoa, sci
    use deck, only: deck_t
    use fptraps, only: traps_off, traps_restore, NTRAPS
    use lines, only: read_line
    implicit none
    private

    !> A record: time from release (s), the measured value (rad or rad/s) and, when the
    !! record has a third column, each sample's standard uncertainty.
    type, public :: record_t
        real(dp), allocatable :: t(:), v(:), u(:)
        logical :: has_u = .false.
    end type record_t

    public :: read_record, record_file, mean_period

    integer, parameter, public :: MIN_SAMPLES = 20          !! shortest record
    integer, parameter, public :: MAX_SAMPLES = 2000000     !! longest record
    integer, parameter :: MAX_RECORD_LINE = 4096    !! longest line of a record
    !> Largest recorded value: rad (angle) or rad per unit of tau (rate, W/sqrt(g/b')); a
    !! standard uncertainty (column 3) from U_MIN to VALUE_MAX in the same units (a smaller
    !! one makes weights 1/u that overflow the fit's sum of squares).
    real(dp), parameter, public :: VALUE_MAX = 1.0e3_dp, U_MIN = 1.0e-12_dp

contains

    !> Read and check the record of a deck (d%record_path): a whitespace table, '#' starts
    !! a comment, blank lines skipped; column 1 time (s) strictly increasing, column 2 the
    !! measured value (|value| <= VALUE_MAX rad, or VALUE_MAX sqrt(g/b') rad/s for a rate),
    !! an optional column 3 its standard uncertainty (U_MIN ... VALUE_MAX in those units);
    !! every data line with the same number of columns, every value finite; at least
    !! MIN_SAMPLES samples.  Numbers beyond the range of real(dp) (1e400) are read with the
    !! floating-point traps off and refused as not finite.  ERR_DECK naming the record, the
    !! line, what is wrong and what is allowed.
    subroutine read_record(d, rec, stat)
        type(deck_t), intent(in) :: d           !! the deck (record, record_path)
        type(record_t), intent(out) :: rec
        type(status_t), intent(out) :: stat     !! ERR_DECK
        character(len=MAX_RECORD_LINE + 1) :: line
        character(len=512) :: msg
        character(len=:), allocatable :: head, path, whole
        real(dp) :: x(3), scale
        real(dp), allocatable :: t(:), v(:), uu(:)
        integer :: u, ios, nline, ncol, n, k, ncol1
        logical :: halting(NTRAPS)
        character(len=:), allocatable :: units, per_tau
        stat%code = 0
        head = '&measurement record = '''//trim(d%record)//''': '
        scale = 1.0_dp
        units = ' rad'
        per_tau = ''
        if (trim(d%quantity) == 'rate') then
            scale = sqrt(d%g/d%b_prime)
            units = ' rad/s'
            per_tau = ' (= '//sci(VALUE_MAX)//' sqrt(g/b_prime))'
        end if
        path = record_file(d)
        open (newunit=u, file=path, status='old', action='read', form='formatted', &
              access='sequential', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, head//'cannot open '//path//': '// &
                trim(msg)//'; allowed: a file relative to the deck''s folder, or an absolute path')
            return
        end if
        allocate (t(1024), v(1024), uu(1024))
        n = 0
        nline = 0
        ncol1 = 0
        call traps_off(halting)
        do
            ! a line of any length is read only up to MAX_RECORD_LINE + 1 characters (a file
            ! without line ends, /dev/zero, ends at once)
            call read_line(u, whole, ios, msg, MAX_RECORD_LINE)
            if (is_iostat_end(ios)) exit
            nline = nline + 1
            if (ios /= 0) then
                call fail('cannot read line '//itoa(nline)//': '//trim(msg))
                return
            end if
            ! the whole text read, blanks included: a longer line is cut where read_line
            ! stopped, and its rest would be read as the next line
            if (len(whole) > MAX_RECORD_LINE) then
                call fail('line '//itoa(nline)//' is longer than '//itoa(MAX_RECORD_LINE)// &
                    ' characters; allowed: lines of at most '//itoa(MAX_RECORD_LINE))
                return
            end if
            line = whole
            k = index(line, '#')
            if (k > 0) line(k:) = ' '
            call split(line, x, ncol, msg)
            if (len_trim(msg) > 0) then
                call fail('line '//itoa(nline)//': '//trim(msg))
                return
            end if
            if (ncol == 0) cycle
            if (ncol1 == 0) ncol1 = ncol
            if (ncol < 2 .or. ncol > 3 .or. ncol /= ncol1) then
                call fail('line '//itoa(nline)//': '//itoa(ncol)//' columns; allowed: every '// &
                    'line with 2 columns (time in s, value) or every line with 3 (and its '// &
                    'standard uncertainty)')
                return
            end if
            if (.not. all(ieee_is_finite(x(1:ncol)))) then
                call fail('line '//itoa(nline)//': a value is not a finite number (NaN, Inf); '// &
                    'allowed: finite numbers')
                return
            end if
            if (n > 0) then
                if (.not. (x(1) > t(n))) then
                    call fail('line '//itoa(nline)//': time '//sci(x(1), 6)// &
                        ' s is not after the previous sample''s '//sci(t(n), 6)// &
                        ' s; allowed: column 1 strictly increasing (s from release)')
                    return
                end if
            end if
            if (abs(x(2)) > VALUE_MAX*scale) then
                call fail('line '//itoa(nline)//': value '//sci(x(2))//' is too large; '// &
                    'allowed: |value| <= '//sci(VALUE_MAX*scale)//units//per_tau)
                return
            end if
            if (ncol == 3) then
                if (.not. (x(3) >= U_MIN*scale .and. x(3) <= VALUE_MAX*scale)) then
                    call fail('line '//itoa(nline)//': standard uncertainty '//sci(x(3))// &
                        ' is out of range; allowed: column 3 from '//sci(U_MIN*scale)// &
                        ' to '//sci(VALUE_MAX*scale)//units)
                    return
                end if
            end if
            if (n == MAX_SAMPLES) then
                call fail('more than '//itoa(MAX_SAMPLES)//' samples; allowed: at most '// &
                    itoa(MAX_SAMPLES))
                return
            end if
            if (n == size(t)) then
                t = [t, t]
                v = [v, v]
                uu = [uu, uu]
            end if
            n = n + 1
            t(n) = x(1)
            v(n) = x(2)
            uu(n) = x(3)
        end do
        call traps_restore(halting)
        close (u)
        if (n < MIN_SAMPLES) then
            call set_error(stat, ERR_DECK, head//itoa(n)//' samples; allowed: at least '// &
                itoa(MIN_SAMPLES))
            return
        end if
        rec%t = t(1:n)
        rec%v = v(1:n)
        rec%has_u = ncol1 == 3
        if (rec%has_u) then
            rec%u = uu(1:n)
        else
            allocate (rec%u(n))
            rec%u = 1.0_dp
        end if
    contains
        subroutine fail(what)
            character(len=*), intent(in) :: what
            call traps_restore(halting)
            call set_error(stat, ERR_DECK, head//what)
            close (u)
        end subroutine fail
    end subroutine read_record

    !> The record file of a deck: &measurement record relative to the deck's folder
    !! (d%record_path), or as given.
    pure function record_file(d) result(path)
        type(deck_t), intent(in) :: d
        character(len=:), allocatable :: path
        path = trim(d%record)
        if (allocated(d%record_path)) path = d%record_path
    end function record_file

    !> The numbers of one line (blanks, tabs or commas between them): up to 3 in x, ncol of
    !! them (4 when there are more); msg names a token that is not a number.
    subroutine split(line, x, ncol, msg)
        character(len=*), intent(in) :: line
        real(dp), intent(out) :: x(3)
        integer, intent(out) :: ncol
        character(len=*), intent(out) :: msg
        integer :: i, j, ios
        real(dp) :: val
        x = 0.0_dp
        ncol = 0
        msg = ''
        i = 1
        do
            do while (i <= len(line))
                if (index(' ,'//achar(9)//achar(13), line(i:i)) == 0) exit
                i = i + 1
            end do
            if (i > len(line)) return
            j = i
            do while (j <= len(line))
                if (index(' ,'//achar(9)//achar(13), line(j:j)) > 0) exit
                j = j + 1
            end do
            if (verify(line(i:j - 1), '0123456789+-.eEdDnNaAiIfF') /= 0) then
                msg = '''' // line(i:min(j - 1, i + 30)) // ''' is not a number'
                return
            end if
            read (line(i:j - 1), *, iostat=ios) val
            if (ios /= 0) then
                msg = '''' // line(i:min(j - 1, i + 30)) // ''' is not a number'
                return
            end if
            ncol = min(ncol + 1, 4)
            if (ncol <= 3) x(ncol) = val
            i = j
        end do
    end subroutine split

    !> The record's mean period (s): twice the mean spacing of the crossings of its mean
    !! value, up and down (linear interpolation between samples; a crossing counts only
    !! after the signal has been beyond the mean, on the side it leaves, by a tenth of its
    !! largest excursion, so noise does not add crossings).  0 when fewer than two crossings.
    function mean_period(rec) result(tp)
        type(record_t), intent(in) :: rec
        real(dp) :: tp
        real(dp) :: mean, band, tc, t_first, t_last, a, b
        integer :: i, nc, side
        tp = 0.0_dp
        mean = sum(rec%v)/size(rec%v)
        band = 0.1_dp*maxval(abs(rec%v - mean))
        side = 0                                ! -1 below the band, +1 above, 0 not yet
        nc = 0
        t_first = 0.0_dp
        t_last = 0.0_dp
        do i = 2, size(rec%v)
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
