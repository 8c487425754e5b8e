!> Numbers as text for messages and headers: integers without blanks, reals in scientific
!! notation that always keeps its E (a plain `es10.3` prints 1e300 as `1.000+300`, which
!! no reader takes for a number).
module text
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use kinds, only: dp
    use fptraps, only: traps_off, traps_restore, NTRAPS
    implicit none
    private

    public :: itoa, sci, fixed, lead_zero, rshort, rlist_short
    public :: lower, is_ident, next_word, count_words, commas, clip, quoted

    !> Longest value quoted in a message (characters; clip)
    integer, parameter :: CLIP_LEN = 60

contains

    !> An integer without blanks: 42, -7.
    pure function itoa(i) result(s)
        integer, intent(in) :: i                    !! value
        character(len=:), allocatable :: s
        character(len=16) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function itoa

    !> A real in scientific notation with `digits` digits after the point and an exponent of
    !! two or three digits: 1.000E+300, -4.352E-14, 2.214E+00; NaN, Inf and -Inf as such.
    pure function sci(x, digits) result(s)
        real(dp), intent(in) :: x                   !! value
        integer, intent(in), optional :: digits     !! digits after the point (default 3, 0..17)
        character(len=:), allocatable :: s
        character(len=40) :: buf
        integer :: nd, ie
        if (ieee_is_nan(x)) then
            s = 'NaN'
            return
        end if
        if (.not. ieee_is_finite(x)) then
            s = merge('-Inf', ' Inf', x < 0.0_dp)
            s = trim(adjustl(s))
            return
        end if
        nd = 3
        if (present(digits)) nd = max(0, min(17, digits))
        write (buf, '(es40.'//itoa(nd)//'e3)') x
        s = trim(adjustl(buf))
        ie = index(s, 'E')
        ! E+300 stays, E-014 -> E-14
        if (ie > 0 .and. len(s) == ie + 4) then
            if (s(ie + 2:ie + 2) == '0') s = s(1:ie + 1)//s(ie + 3:)
        end if
    end function sci

    !> A real in fixed notation with `digits` digits after the point and a zero before it:
    !! 0.050000, -0.5, 12.0 (the run-time library's f0.d leaves the zero out); from 1e9 on in
    !! scientific notation with as many digits (1.000000E+116: a message stays one short
    !! line); NaN, Inf and -Inf as such.
    pure function fixed(x, digits) result(s)
        real(dp), intent(in) :: x                   !! value
        integer, intent(in) :: digits               !! digits after the point (0..17)
        character(len=:), allocatable :: s
        character(len=48) :: buf
        if (.not. (abs(x) < 1.0e9_dp)) then
            s = sci(x, digits)
            return
        end if
        write (buf, '(f0.'//itoa(max(0, min(17, digits)))//')') x
        s = lead_zero(buf)
    end function fixed

    !> A number's text without blanks and with a zero before a leading point: .5 -> 0.5,
    !! -.5 -> -0.5.
    pure function lead_zero(buf) result(s)
        character(len=*), intent(in) :: buf         !! the number, blanks around it allowed
        character(len=:), allocatable :: s
        s = trim(adjustl(buf))
        if (len(s) == 0) return
        if (s(1:1) == '.') s = '0'//s
        if (len(s) > 1) then
            if (s(1:2) == '-.') s = '-0'//s(2:)
        end if
    end function lead_zero

    !> Shortest real that reads back exactly (for messages): 180, 0.3, 1e-15, 1.7e308.
    function rshort(x) result(s)
        real(dp), intent(in) :: x                   !! value
        character(len=:), allocatable :: s
        character(len=48) :: buf
        integer :: k, ie
        logical :: halting(NTRAPS), fixed
        if (.not. ieee_is_finite(x)) then
            write (buf, '(g0)') x
            s = trim(adjustl(buf))
            return
        end if
        call traps_off(halting)     ! a rounded 1.7e308 reads back as an overflow
        fixed = .false.
        if (x == 0.0_dp .or. (abs(x) >= 1.0e-4_dp .and. abs(x) < 1.0e15_dp)) then
            k = fewest_digits(x, .true.)
            fixed = k >= 0
        end if
        if (fixed) then
            write (buf, '(f48.'//itoa(k)//')') x
            s = lead_zero(buf)
            if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
        else
            k = fewest_digits(x, .false.)
            if (k < 0) k = 16
            write (buf, '(es48.'//itoa(k)//'e3)') x
            s = trim(adjustl(buf))
            ie = index(s, 'E')
            ! 1.E-015 -> 1e-15, 1.7E+308 -> 1.7e308
            k = ie + 2
            do while (k < len(s))
                if (s(k:k) /= '0') exit
                k = k + 1
            end do
            if (s(ie + 1:ie + 1) == '-') then
                s = s(1:ie - 1)//'e-'//s(k:)
            else
                s = s(1:ie - 1)//'e'//s(k:)
            end if
            ie = index(s, '.e')
            if (ie > 0) s = s(1:ie - 1)//s(ie + 1:)
        end if
        call traps_restore(halting)
    end function rshort

    !> The fewest digits after the point, k, with which x written in fixed (f48.k, k <= 24) or
    !! scientific notation (es48.ke3, k <= 16) reads back exactly; -1 when none does.  The
    !! same k as trying k = 0, 1, 2, ... in turn, in about four trials instead of up to 25:
    !! k = 0, then the candidate from x's 16-digit text (its digits without trailing zeros),
    !! then down while a shorter text still reads back.  Where x is not a power of two the
    !! values that read back as x lie symmetrically around it, and a text with one digit more
    !! is never further from x, so the texts that read back are those from the fewest digits
    !! on; powers of two (asymmetric) and surprises take the trials in turn.  Traps off.
    function fewest_digits(x, fixed_form) result(k)
        real(dp), intent(in) :: x                   !! finite value
        logical, intent(in) :: fixed_form           !! f48.k, else es48.ke3
        integer :: k
        character(len=48) :: buf
        integer :: kmax, kc, p, e10, i0, ie, j
        kmax = merge(24, 16, fixed_form)
        k = 0
        if (reads_back(k)) return
        if (abs(fraction(x)) /= 0.5_dp) then
            write (buf, '(es48.15e3)') x
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
        logical function reads_back(kk)
            integer, intent(in) :: kk
            character(len=48) :: txt
            real(dp) :: y
            integer :: ios
            if (fixed_form) then
                write (txt, '(f48.'//itoa(kk)//')') x
            else
                write (txt, '(es48.'//itoa(kk)//'e3)') x
            end if
            read (txt, *, iostat=ios) y
            reads_back = ios == 0 .and. y == x
        end function reads_back
    end function fewest_digits

    function rlist_short(x) result(s)
        real(dp), intent(in) :: x(:)                !! values
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(x)
            if (i > 1) s = s//', '
            s = s//rshort(x(i))
        end do
    end function rlist_short

    !> Next blank-separated word of s after position i2: s(i1:i2); i1 = 0 when none.
    pure subroutine next_word(s, i2, i1)
        character(len=*), intent(in) :: s           !! text
        integer, intent(inout) :: i2                !! in: end of previous word; out: end
        integer, intent(out) :: i1                  !! start of the word, 0 when none
        integer :: i
        i1 = 0
        i = i2 + 1
        do while (i <= len(s))
            if (s(i:i) /= ' ') exit
            i = i + 1
        end do
        if (i > len(s)) return
        i1 = i
        do while (i <= len(s))
            if (s(i:i) == ' ') exit
            i = i + 1
        end do
        i2 = i - 1
    end subroutine next_word

    !> Number of blank-separated words in s.
    pure integer function count_words(s) result(n)
        character(len=*), intent(in) :: s
        integer :: i1, i2
        n = 0
        i2 = 0
        do
            call next_word(s, i2, i1)
            if (i1 == 0) exit
            n = n + 1
        end do
    end function count_words

    pure function lower(s) result(t)
        character(len=*), intent(in) :: s           !! any text
        character(len=len(s)) :: t
        integer :: i
        t = s
        do i = 1, len(s)
            if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') t(i:i) = achar(iachar(s(i:i)) + 32)
        end do
    end function lower

    pure logical function is_ident(c)
        character, intent(in) :: c                  !! one character
        is_ident = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') .or. &
                   (c >= '0' .and. c <= '9') .or. c == '_'
    end function is_ident

    !> 'a b c' -> 'a, b, c' (or another separator).
    pure function commas(words, sep) result(s)
        character(len=*), intent(in) :: words       !! blank-separated words
        character(len=*), intent(in), optional :: sep   !! separator, default ', '
        character(len=:), allocatable :: s
        integer :: i1, i2
        s = ''
        i2 = 0
        do
            call next_word(words, i2, i1)
            if (i1 == 0) exit
            if (len(s) > 0) then
                if (present(sep)) then
                    s = s//sep
                else
                    s = s//', '
                end if
            end if
            s = s//words(i1:i2)
        end do
    end function commas

    !> s for a message: at most CLIP_LEN characters, longer text cut with '...'.
    pure function clip(s) result(t)
        character(len=*), intent(in) :: s          !! any text
        character(len=:), allocatable :: t
        if (len(s) <= CLIP_LEN) then
            t = s
        else
            t = s(1:CLIP_LEN - 3)//'...'
        end if
    end function clip

    !> Quoted for namelist output, inner quotes doubled.
    pure function quoted(s) result(t)
        character(len=*), intent(in) :: s           !! text
        character(len=:), allocatable :: t
        integer :: i
        t = ''''
        do i = 1, len_trim(s)
            if (s(i:i) == '''') then
                t = t//''''''
            else
                t = t//s(i:i)
            end if
        end do
        t = t//''''
    end function quoted

end module text
