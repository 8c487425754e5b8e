!> rshort's text: the shortest real that reads back exactly, as the run-time library would
!! write and read it, without the library's formatted I/O.
!!
!! The text is the one of trying the edit descriptors f48.k (k = 0, 1, ... while
!! 1e-4 <= |x| < 1e15 or x = 0) or es48.ke3 in turn and keeping the first whose text reads
!! back as x.  Through the library's internal WRITE and READ that took 32,500 instructions
!! a number, and the echo of a Floquet deck's groups 3.6M, a third of the whole process
!! (doc/performance.md); here 1,760 a number.  Each text is module fast_format's, which is
!! the library's character for character, and a text is read back by Clinger's fast path
!! where that is exact: digits whose integer m <= 2^53 and a power of ten 10^q with
!! |q| <= 22 are both exact doubles, so m 10^q (or m / 10^-q) is one correctly rounded
!! operation, the value the library's correctly rounded reading gives.  Other texts (more
!! than 18 digits, larger powers, near the largest real) are read by the library as
!! before.  A text of f48.0 is the nearest integer, which reads back exactly when x is an
!! integer (|x| < 1e15 in fixed notation).  Test: suite deck,
!! "deck: shortest reals of the echo" (rshort against the digits tried in turn through the
!! library).
!!
!! A submodule of text, so that text (used by nearly every module) stays on the module
!! graph's lowest floor while this part uses fast_format.
submodule (text) text_short
    use fast_format, only: es_field, f_field
    implicit none

    !> 10^0 ... 10^22, each exact in double precision (5^22 < 2^53)
    real(dp), parameter :: EXACT10(0:22) = [1.0e0_dp, 1.0e1_dp, 1.0e2_dp, 1.0e3_dp, &
        1.0e4_dp, 1.0e5_dp, 1.0e6_dp, 1.0e7_dp, 1.0e8_dp, 1.0e9_dp, 1.0e10_dp, 1.0e11_dp, &
        1.0e12_dp, 1.0e13_dp, 1.0e14_dp, 1.0e15_dp, 1.0e16_dp, 1.0e17_dp, 1.0e18_dp, &
        1.0e19_dp, 1.0e20_dp, 1.0e21_dp, 1.0e22_dp]
    !> the largest significand read by the fast path: 2^53, every integer up to it exact
    integer(int64), parameter :: FAST_M_MAX = 9007199254740992_int64

contains

    module procedure rshort_text
        character(len=NUM_LEN) :: buf
        integer :: k, ie, n
        logical :: fixed_form
        if (.not. ieee_is_finite(x)) then
            write (buf, '(g0)') x
            s = adjustl(buf)
            return
        end if
        fixed_form = .false.
        if (x == 0.0_dp .or. (abs(x) >= 1.0e-4_dp .and. abs(x) < 1.0e15_dp)) then
            k = fewest_digits(x, .true.)
            fixed_form = k >= 0
        end if
        if (fixed_form) then
            ! the library's f48.k; for k = 0 (x an integer) f48.1's N.0 without its .0
            call f_field(x, max(1, k), buf)
            s = lead_zero_text(buf)
            n = len_trim(s)
            if (k == 0) then
                s(n - 1:n) = ''
            else if (s(n:n) == '.') then
                s(n:n) = ' '
            end if
        else
            k = fewest_digits(x, .false.)
            if (k < 0) k = 16
            call es_field(x, k, buf)            ! the library's es48.ke3
            buf = adjustl(buf)
            n = len_trim(buf)
            ie = index(buf, 'E')
            ! 1.E-015 -> 1e-15, 1.7E+308 -> 1.7e308
            k = ie + 2
            do while (k < n)
                if (buf(k:k) /= '0') exit
                k = k + 1
            end do
            if (buf(ie + 1:ie + 1) == '-') then
                s = buf(1:ie - 1)//'e-'//buf(k:n)
            else
                s = buf(1:ie - 1)//'e'//buf(k:n)
            end if
            ie = index(s, '.e')
            if (ie > 0) s = s(1:ie - 1)//s(ie + 1:)
        end if
    end procedure rshort_text

    !> The fewest digits after the point, k, with which x written in fixed (f48.k, k <= 24) or
    !! scientific notation (es48.ke3, k <= 16) reads back exactly; -1 when none does.  The
    !! same k as trying k = 0, 1, 2, ... in turn, in about four trials instead of up to 25:
    !! k = 0, then the candidate from x's 16-digit text (its digits without trailing zeros),
    !! then down while a shorter text still reads back.  Where x is not a power of two the
    !! values that read back as x lie symmetrically around it, and a text with one digit more
    !! is never further from x, so the texts that read back are those from the fewest digits
    !! on; powers of two (asymmetric) and surprises take the trials in turn.  A text beyond
    !! the largest real (1.7976931348623157e308 rounded up) is not read: it cannot read
    !! back, and reading it would overflow (a trap in the checking build).
    pure function fewest_digits(x, fixed_form) result(k)
        real(dp), intent(in) :: x                   !! finite value
        logical, intent(in) :: fixed_form           !! f48.k, else es48.ke3
        integer :: k
        character(len=48) :: buf
        integer :: kmax, kc, p, e10, i0, ie, j
        kmax = merge(24, 16, fixed_form)
        k = 0
        if (reads_back(k)) return
        if (abs(fraction(x)) /= 0.5_dp) then
            call es_field(x, 15, buf)           ! the library's es48.15e3
            buf = adjustl(buf)
            i0 = index(buf, '.')
            ie = index(buf, 'E')
            p = 16
            do j = ie - 1, i0 + 1, -1
                if (buf(j:j) /= '0') exit
                p = p - 1
            end do
            e10 = 0
            do j = ie + 2, len_trim(buf)
                e10 = 10*e10 + (iachar(buf(j:j)) - iachar('0'))
            end do
            if (buf(ie + 1:ie + 1) == '-') e10 = -e10
            kc = p - 1
            if (fixed_form) kc = p - 1 - e10
            kc = max(1, kc)
            if (kc <= kmax) then
                if (reads_back(kc)) then
                    do while (kc > 1)
                        if (.not. reads_back(kc - 1)) exit
                        kc = kc - 1
                    end do
                    k = kc
                    return
                end if
            end if
        end if
        do k = 1, kmax
            if (reads_back(k)) return
        end do
        k = -1
    contains
        !> x written with kk digits after the point reads back as x.
        pure logical function reads_back(kk)
            integer, intent(in) :: kk
            character(len=48) :: txt
            real(dp) :: y, mant
            integer :: ios, ie2
            logical :: fast
            if (fixed_form .and. kk == 0) then
                ! f48.0 is the nearest integer (|x| < 1e15: exact), which is x if x is one
                reads_back = x == aint(x)
                return
            end if
            if (fixed_form) then
                call f_field(x, kk, txt)
            else
                call es_field(x, kk, txt)
            end if
            reads_back = .false.
            if (abs(x) > 1.0e308_dp) then
                ! beyond the largest real?  Its mantissa alone cannot overflow
                txt = adjustl(txt)
                ie2 = index(txt, 'E')
                if (ie2 > 1) then
                    read (txt(1:ie2 - 1), *, iostat=ios) mant
                    if (ios /= 0) return
                    if (index(txt, 'E+309') > 0) return
                    if (index(txt, 'E+308') > 0 .and. abs(mant) > 1.7976931348623157_dp) return
                end if
            end if
            call fast_value(txt, y, fast)
            if (fast) then
                ios = 0
            else
                read (txt, *, iostat=ios) y
            end if
            reads_back = ios == 0 .and. y == x
        end function reads_back
    end function fewest_digits

    !> The value of a number's text as f_field or es_field writes it (blanks, an optional
    !! minus, digits with one point, an optional E and signed exponent), where Clinger's fast
    !! path makes it exact: at most 18 significant digits whose integer m <= 2^53, scaled by
    !! 10^q with |q| <= 22 in one correctly rounded operation.  .false. (y = 0) for any
    !! other text, which the caller then reads through the library.
    pure subroutine fast_value(txt, y, ok)
        character(len=*), intent(in) :: txt         !! the number's text
        real(dp), intent(out) :: y                  !! its value when ok
        logical, intent(out) :: ok                  !! the text was read
        integer(int64) :: m
        integer :: i, n, nd, ndig, q, e, d
        logical :: neg, point, eneg
        ok = .false.
        y = 0.0_dp
        n = len_trim(txt)
        i = 1
        do while (i <= n)
            if (txt(i:i) /= ' ') exit
            i = i + 1
        end do
        neg = .false.
        if (i <= n) then
            if (txt(i:i) == '-') then
                neg = .true.
                i = i + 1
            end if
        end if
        m = 0
        nd = 0              ! significant digits (from the first non-zero one)
        ndig = 0            ! all digits
        q = 0
        point = .false.
        do while (i <= n)
            d = iachar(txt(i:i)) - iachar('0')
            if (d >= 0 .and. d <= 9) then
                if (m > 0 .or. d > 0) nd = nd + 1
                if (nd > 18) return
                m = 10*m + d
                ndig = ndig + 1
                if (point) q = q - 1
            else if (txt(i:i) == '.' .and. .not. point) then
                point = .true.
            else
                exit
            end if
            i = i + 1
        end do
        if (ndig == 0) return
        if (i <= n) then
            if (txt(i:i) /= 'E') return
            i = i + 1
            if (i > n) return
            eneg = txt(i:i) == '-'
            if (txt(i:i) == '-' .or. txt(i:i) == '+') i = i + 1
            if (i > n .or. n - i > 3) return
            e = 0
            do while (i <= n)
                d = iachar(txt(i:i)) - iachar('0')
                if (d < 0 .or. d > 9) return
                e = 10*e + d
                i = i + 1
            end do
            q = q + merge(-e, e, eneg)
        end if
        if (m > FAST_M_MAX .or. q < -22 .or. q > 22) return
        y = real(m, dp)
        if (q >= 0) then
            y = y*EXACT10(q)
        else
            y = y/EXACT10(-q)
        end if
        if (neg) y = -y
        ok = .true.
    end subroutine fast_value

end submodule text_short
