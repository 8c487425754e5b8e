!> Fast text of reals for the data files: exactly the text the run-time library writes for
!! the edit descriptors ESw.dE3 and Fw.d, made without the library's formatting machinery,
!! which costs far more per real (doc/performance.md).
!!
!! Method.  A finite normal double is |x| = m 2^k with the integer significand
!! 2^52 <= m < 2^53.  The decimal digits of ESw.dE3 are N = |x| 10^q rounded to the nearest
!! integer (ties to even, as the library's default rounding mode), with q = d - e chosen so
!! that 10^d <= N < 10^(d+1); for Fw.d, q = d.  The powers of ten are held as a table
!! 10^q ~ P(q) 2^T(q), P(q) a 73-bit integer (built when the module is compiled, from the
!! quadruple-precision value of 10^q: no work at load time), so m P(q) fits a 128-bit
!! integer and |x| 10^q = m P(q) 2^(k + T(q)) is a 126-bit fixed-point number: its integer
!! part is N (before rounding), its fraction decides the rounding.
!!
!! Exactness.  For 0 <= q <= 31, 10^q = 5^q 2^q with 5^q < 2^73 is exact in P(q), so the
!! product is exact and so is the rounding, ties included.  For other q, P(q) carries a
!! relative error below 2^-73, so the fraction is known to within 2^53 units of the 126-bit
!! product; when it lies that close to one half the digits are left to the library (an
!! internal WRITE with the same edit descriptor), as are zero-width cases, non-finite and
!! subnormal x, and fields too narrow for the number (the library's asterisks).  A tie
!! |x| 10^q = N + 1/2 cannot occur for those q with d <= 16, so the text is the library's
!! for every x: same characters, same blanks, same signs (a negative zero keeps its minus).
!! Tests (suite `fast_format`) compare both texts character by character.
module fast_format
    use kinds, only: dp
    implicit none
    private

    public :: es_field, f_field

    integer, parameter :: qp = selected_real_kind(30)     !! only for the table, at compile time
    integer, parameter :: i8 = selected_int_kind(18)
    integer, parameter :: i16 = selected_int_kind(38)
    integer, parameter :: QMIN = -310, QMAX = 330         !! every normal x, d <= 16
    integer, parameter :: QEXACT = 31                     !! 0 <= q <= QEXACT: P(q) exact
    integer(i8), parameter :: POW10(0:18) = [1_i8, 10_i8, 100_i8, 1000_i8, 10000_i8, &
        100000_i8, 1000000_i8, 10000000_i8, 100000000_i8, 1000000000_i8, 10000000000_i8, &
        100000000000_i8, 1000000000000_i8, 10000000000000_i8, 100000000000000_i8, &
        1000000000000000_i8, 10000000000000000_i8, 100000000000000000_i8, &
        1000000000000000000_i8]
    !> log10(2), to guess the decimal exponent from the binary one
    real(dp), parameter :: LOG10_2 = 0.30102999566398119521_dp
    !> the product's error bound for inexact P(q): 2^53 units, taken as 2^55
    integer(i16), parameter :: MARGIN = shiftl(1_i16, 55)

contains

    !> ESw.dE3 of x into field (w = len(field)): the library's text, e.g. for ES24.15E3
    !! `  1.234567890123457E-003` and ` -5.000000000000000E-001`.
    !!
    !! x     [in]  the value.
    !! d     [in]  digits after the decimal point, 0 <= d <= 16 (the library's for others).
    !! field [out] character(len=w): the text, right-justified as the library writes it.
    pure subroutine es_field(x, d, field)
        real(dp), intent(in) :: x
        integer, intent(in) :: d
        character(len=*), intent(out) :: field
        integer(i8) :: m, n
        integer :: k, e, q, w, nc, pos, ae
        logical :: neg, ok
        w = len(field)
        call split(x, m, k, neg, ok)
        if (.not. ok .or. d < 0 .or. d > 16) then
            call library_field(x, .true., d, field)
            return
        end if
        nc = d + 7                        ! D.ddd...E+xxx (d = 0: D.E+xxx)
        if (neg) nc = nc + 1
        if (w < nc) then
            call library_field(x, .true., d, field)
            return
        end if
        if (m == 0) then
            n = 0
            e = 0
        else
            ! decimal exponent e: 10^e <= |x| < 10^(e+1); the guess from the binary exponent
            ! is e or e - 1.  With the guess, n > 10^(d+1) shows it was e - 1; n = 10^(d+1)
            ! (|x| 10^q within 1/2 of it) gives the same text either way: 1.000...E(e+1).
            e = floor((k + 52)*LOG10_2)
            q = d - e
            call scaled(m, k, q, n, ok)
            if (ok .and. n > POW10(d + 1)) then
                e = e + 1
                q = q - 1
                call scaled(m, k, q, n, ok)
            end if
            if (.not. ok) then
                call library_field(x, .true., d, field)
                return
            end if
            if (n == POW10(d + 1)) then   ! rounded up to the next decade
                n = POW10(d)
                e = e + 1
            end if
        end if
        call start_field(field, nc, neg, pos)
        ! leading digit, point, d digits
        call put_digits(n/POW10(d), 1, field(pos:pos))
        field(pos + 1:pos + 1) = '.'
        if (d > 0) call put_digits(mod(n, POW10(d)), d, field(pos + 2:pos + 1 + d))
        pos = pos + 2 + d
        field(pos:pos) = 'E'
        field(pos + 1:pos + 1) = merge('-', '+', e < 0)
        ae = abs(e)
        call put_digits(int(ae, i8), 3, field(pos + 2:pos + 4))
    end subroutine es_field

    !> Fw.d of x into field (w = len(field)): the library's text, e.g. for F14.6
    !! `     60.000000`, `      0.150000`, `     -0.000000` (a negative value that rounds
    !! to zero keeps its sign, as the library writes it).
    !!
    !! x     [in]  the value.
    !! d     [in]  digits after the decimal point, 1 <= d <= 17 (the library's for others).
    !! field [out] character(len=w): the text, right-justified.
    pure subroutine f_field(x, d, field)
        real(dp), intent(in) :: x
        integer, intent(in) :: d
        character(len=*), intent(out) :: field
        integer(i8) :: m, n, ip
        integer :: k, w, nint_digits, nc, pos
        logical :: neg, ok
        w = len(field)
        call split(x, m, k, neg, ok)
        if (.not. ok .or. d < 1 .or. d > 17) then
            call library_field(x, .false., d, field)
            return
        end if
        n = 0
        ! |x| < 0.3 10^-d rounds to zero; above it the product's shift s is at most 127
        if (abs(x) >= 0.3_dp*10.0_dp**(-d)) then
            call scaled(m, k, d, n, ok)
            if (.not. ok) then
                call library_field(x, .false., d, field)
                return
            end if
        end if
        ip = n/POW10(d)
        nint_digits = 1
        do while (nint_digits < 18)
            if (ip < POW10(nint_digits)) exit
            nint_digits = nint_digits + 1
        end do
        nc = nint_digits + 1 + d
        if (neg) nc = nc + 1
        if (w < nc) then
            call library_field(x, .false., d, field)
            return
        end if
        call start_field(field, nc, neg, pos)
        call put_digits(ip, nint_digits, field(pos:pos + nint_digits - 1))
        pos = pos + nint_digits
        field(pos:pos) = '.'
        call put_digits(mod(n, POW10(d)), d, field(pos + 1:pos + d))
    end subroutine f_field

    !> Blanks before the nc characters of the number (right-justified in field) and its
    !! minus sign when neg; pos is where the digits start.
    pure subroutine start_field(field, nc, neg, pos)
        character(len=*), intent(inout) :: field
        integer, intent(in) :: nc               !! characters of the number, sign included
        logical, intent(in) :: neg
        integer, intent(out) :: pos
        pos = len(field) - nc + 1
        field(1:pos - 1) = ''
        if (neg) then
            field(pos:pos) = '-'
            pos = pos + 1
        end if
    end subroutine start_field

    !> |x| = m 2^k (2^52 <= m < 2^53) and the sign bit of x; m = 0 for a zero; ok = .false.
    !! for a NaN, an infinity or a subnormal (left to the library).
    pure subroutine split(x, m, k, neg, ok)
        real(dp), intent(in) :: x
        integer(i8), intent(out) :: m
        integer, intent(out) :: k
        logical, intent(out) :: neg, ok
        integer(i8) :: bits
        integer :: be
        bits = transfer(x, bits)
        neg = bits < 0
        be = int(ibits(bits, 52, 11))
        m = ibits(bits, 0, 52)
        ok = .true.
        k = 0
        if (be == 0) then
            ok = m == 0                   ! zero is fine, subnormals go to the library
        else if (be == 2047) then
            ok = .false.
        else
            m = ior(m, shiftl(1_i8, 52))
            k = be - 1075
        end if
    end subroutine split

    !> n = m 2^k 10^q rounded to the nearest integer, ties to even; ok = .false. when the
    !! rounding cannot be decided from the table (see the module header), or q or the
    !! product's shift is out of range (the shift s >= 65 keeps n below 2^61).
    pure subroutine scaled(m, k, q, n, ok)
        integer(i8), intent(in) :: m            !! significand, 2^52 <= m < 2^53
        integer, intent(in) :: k, q             !! binary exponent of x, power of ten
        integer(i8), intent(out) :: n
        logical, intent(out) :: ok
        integer :: i
        !> 10^q ~ P10(q) 2^T10(q), 2^72 <= P10(q) < 2^73, the nearest integer to the
        !! quadruple-precision 10^q (constants: computed by the compiler)
        integer(i16), parameter :: P10(QMIN:QMAX) = &
            [(nint(fraction(10.0_qp**i)*2.0_qp**73, i16), i = QMIN, QMAX)]
        integer, parameter :: T10(QMIN:QMAX) = [(exponent(10.0_qp**i) - 73, i = QMIN, QMAX)]
        integer(i16) :: prod, r, half
        integer :: s
        n = 0
        ok = q >= QMIN .and. q <= QMAX
        if (.not. ok) return
        s = -(k + T10(q))
        ok = s >= 65 .and. s <= 127
        if (.not. ok) return
        prod = int(m, i16)*P10(q)
        n = int(shiftr(prod, s), i8)
        r = prod - shiftl(int(n, i16), s)
        half = shiftl(1_i16, s - 1)
        if (q < 0 .or. q > QEXACT) then
            if (abs(r - half) <= MARGIN) then
                ok = .false.
                return
            end if
        end if
        if (r > half .or. (r == half .and. btest(n, 0))) n = n + 1
    end subroutine scaled

    !> The nd decimal digits of v >= 0 (leading zeros included) into s(1:nd), two at a time.
    pure subroutine put_digits(v, nd, s)
        integer(i8), intent(in) :: v
        integer, intent(in) :: nd
        character(len=*), intent(out) :: s
        character(len=*), parameter :: PAIRS = &
            '00010203040506070809101112131415161718192021222324252627282930313233343536373839'// &
            '40414243444546474849505152535455565758596061626364656667686970717273747576777879'// &
            '8081828384858687888990919293949596979899'
        integer(i8) :: t, qq
        integer :: i, j
        t = v
        i = nd
        do while (i > 1)
            qq = t/100
            j = 2*int(t - 100*qq)
            s(i - 1:i) = PAIRS(j + 1:j + 2)
            t = qq
            i = i - 2
        end do
        if (i == 1) s(1:1) = achar(48 + int(t))
    end subroutine put_digits

    !> The library's text (internal WRITE) for ESw.dE3 (es = .true.) or Fw.d.
    pure subroutine library_field(x, es, d, field)
        real(dp), intent(in) :: x
        logical, intent(in) :: es
        integer, intent(in) :: d
        character(len=*), intent(out) :: field
        character(len=32) :: fmt
        write (fmt, '(a,i0,a,i0,a)') '('//merge('es', 'f ', es), len(field), '.', d, &
            merge('e3)', ')  ', es)
        write (field, fmt) x
    end subroutine library_field

end module fast_format
