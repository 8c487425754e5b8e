!> Numbers as text for messages and headers: integers without blanks, reals in scientific
!! notation that always keeps its E (a plain `es10.3` prints 1e300 as `1.000+300`, which
!! no reader takes for a number).
!!
!! Thread-safe: no module variable, no SAVE, every function pure, and no
!! function returns `character(len=:), allocatable`.  gfortran 12 keeps the length of such
!! a result, at every place that calls the function, in a static variable (its tree dump
!! shows `static integer(kind=8) slen.N`): two threads calling one place at once mixed
!! their lengths, which cut numbers short, lost a format's digits ("Nonnegative width
!! required in format" at the old text.f90:42) and corrupted the heap, in Monte Carlo runs
!! whose samples failed on two threads.  Here each result's length is a specification
!! expression (the length of the text made into a fixed buffer by the *_text functions),
!! which the caller evaluates in its own frame.  Test: suite fast_format, "text: numbers
!! made on two threads at once".
module text
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    implicit none
    private

    public :: itoa, sci, fixed, lead_zero, rshort, rlist_short
    public :: lower, is_ident, next_word, count_words, commas, clip, quoted
    ! the specification functions of the results' lengths (the callers evaluate them)
    public :: itoa_text, sci_text, fixed_text, lead_zero_text, rshort_text, rlist_len, &
              quoted_len, commas_len

    !> Longest value quoted in a message (characters; clip)
    integer, parameter :: CLIP_LEN = 60
    !> The buffer of one number's text (sci, fixed, rshort: at most 28 characters)
    integer, parameter :: NUM_LEN = 48

    !> A real in scientific notation: sci(x) with 3 digits after the point, sci(x, digits).
    interface sci
        module procedure sci_3, sci_d
    end interface sci

    !> 'a b c' -> 'a, b, c': commas(words), or commas(words, sep) with another separator.
    interface commas
        module procedure commas_default, commas_sep
    end interface commas

    interface
        !> rshort's text, left-justified (submodule text_short: the run-time library's text,
        !! made without its formatted I/O).
        module pure function rshort_text(x) result(s)
            real(dp), intent(in) :: x               !! value
            character(len=NUM_LEN) :: s
        end function rshort_text
    end interface

contains

    !> An integer without blanks: 42, -7.
    pure function itoa(i) result(s)
        integer, intent(in) :: i                    !! value
        character(len=len_trim(itoa_text(i))) :: s
        s = itoa_text(i)
    end function itoa

    !> itoa's text, left-justified in 12 characters: digits by division, no I/O.
    pure function itoa_text(i) result(s)
        integer, intent(in) :: i                    !! value
        character(len=12) :: s
        character(len=12) :: buf
        integer(int64) :: v
        integer :: k
        v = abs(int(i, int64))
        k = len(buf) + 1
        do
            k = k - 1
            buf(k:k) = achar(iachar('0') + int(mod(v, 10_int64)))
            v = v/10_int64
            if (v == 0_int64) exit
        end do
        if (i < 0) then
            k = k - 1
            buf(k:k) = '-'
        end if
        s = buf(k:)
    end function itoa_text

    !> A real in scientific notation with 3 digits after the point and an exponent of two
    !! or three digits: 1.000E+300, -4.352E-14, 2.214E+00; NaN, Inf and -Inf as such.
    pure function sci_3(x) result(s)
        real(dp), intent(in) :: x                   !! value
        character(len=len_trim(sci_text(x, 3))) :: s
        s = sci_text(x, 3)
    end function sci_3

    !> As sci(x) with `digits` digits after the point (0..17).
    pure function sci_d(x, digits) result(s)
        real(dp), intent(in) :: x                   !! value
        integer, intent(in) :: digits               !! digits after the point (0..17)
        character(len=len_trim(sci_text(x, digits))) :: s
        s = sci_text(x, digits)
    end function sci_d

    !> sci's text, left-justified.
    pure function sci_text(x, digits) result(s)
        real(dp), intent(in) :: x                   !! value
        integer, intent(in) :: digits               !! digits after the point (0..17)
        character(len=NUM_LEN) :: s
        character(len=40) :: buf
        character(len=16) :: fmt
        integer :: ie, n
        if (ieee_is_nan(x)) then
            s = 'NaN'
            return
        end if
        if (.not. ieee_is_finite(x)) then
            s = merge('-Inf', 'Inf ', x < 0.0_dp)
            return
        end if
        fmt = '(es40.'//itoa(max(0, min(17, digits)))//'e3)'
        write (buf, fmt) x
        s = adjustl(buf)
        n = len_trim(s)
        ie = index(s, 'E')
        ! E+300 stays, E-014 -> E-14
        if (ie > 0 .and. n == ie + 4) then
            if (s(ie + 2:ie + 2) == '0') s = s(1:ie + 1)//s(ie + 3:n)
        end if
    end function sci_text

    !> A real in fixed notation with `digits` digits after the point and a zero before it:
    !! 0.050000, -0.5, 12.0 (the run-time library's f0.d leaves the zero out); from 1e9 on in
    !! scientific notation with as many digits (1.000000E+116: a message stays one short
    !! line); NaN, Inf and -Inf as such.
    pure function fixed(x, digits) result(s)
        real(dp), intent(in) :: x                   !! value
        integer, intent(in) :: digits               !! digits after the point (0..17)
        character(len=len_trim(fixed_text(x, digits))) :: s
        s = fixed_text(x, digits)
    end function fixed

    !> fixed's text, left-justified.
    pure function fixed_text(x, digits) result(s)
        real(dp), intent(in) :: x                   !! value
        integer, intent(in) :: digits               !! digits after the point (0..17)
        character(len=NUM_LEN) :: s
        character(len=NUM_LEN) :: buf
        character(len=16) :: fmt
        if (.not. (abs(x) < 1.0e9_dp)) then
            s = sci_text(x, digits)
            return
        end if
        fmt = '(f0.'//itoa(max(0, min(17, digits)))//')'
        write (buf, fmt) x
        s = lead_zero_text(buf)
    end function fixed_text

    !> A number's text without blanks and with a zero before a leading point: .5 -> 0.5,
    !! -.5 -> -0.5.
    pure function lead_zero(buf) result(s)
        character(len=*), intent(in) :: buf         !! the number, blanks around it allowed
        character(len=len_trim(lead_zero_text(buf))) :: s
        s = lead_zero_text(buf)
    end function lead_zero

    !> lead_zero's text, left-justified (one character longer than buf).
    pure function lead_zero_text(buf) result(s)
        character(len=*), intent(in) :: buf         !! the number, blanks around it allowed
        character(len=len(buf) + 1) :: s
        integer :: n
        s = adjustl(buf)
        n = len_trim(s)
        if (n == 0) return
        if (s(1:1) == '.') then
            s = '0'//s(1:n)
        else if (n > 1) then
            if (s(1:2) == '-.') s = '-0'//s(2:n)
        end if
    end function lead_zero_text

    !> Shortest real that reads back exactly (for messages): 180, 0.3, 1e-15, 1.7e308.
    pure function rshort(x) result(s)
        real(dp), intent(in) :: x                   !! value
        character(len=len_trim(rshort_text(x))) :: s
        s = rshort_text(x)
    end function rshort


    !> rshort of each value, joined by ', '.
    pure function rlist_short(x) result(s)
        real(dp), intent(in) :: x(:)                !! values
        character(len=rlist_len(x)) :: s
        integer :: i, n, m
        n = 0
        do i = 1, size(x)
            if (i > 1) then
                s(n + 1:n + 2) = ', '
                n = n + 2
            end if
            m = len_trim(rshort_text(x(i)))
            s(n + 1:n + m) = rshort_text(x(i))
            n = n + m
        end do
    end function rlist_short

    !> The length of rlist_short(x).
    pure integer function rlist_len(x) result(n)
        real(dp), intent(in) :: x(:)                !! values
        integer :: i
        n = 2*max(0, size(x) - 1)
        do i = 1, size(x)
            n = n + len_trim(rshort_text(x(i)))
        end do
    end function rlist_len

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

    !> 'a b c' -> 'a, b, c'.
    pure function commas_default(words) result(s)
        character(len=*), intent(in) :: words       !! blank-separated words
        character(len=commas_len(words, ', ')) :: s
        call join_words(words, ', ', s)
    end function commas_default

    !> 'a b c' -> 'a'//sep//'b'//sep//'c'.
    pure function commas_sep(words, sep) result(s)
        character(len=*), intent(in) :: words       !! blank-separated words
        character(len=*), intent(in) :: sep         !! separator
        character(len=commas_len(words, sep)) :: s
        call join_words(words, sep, s)
    end function commas_sep

    !> The length of the words joined by sep.
    pure integer function commas_len(words, sep) result(n)
        character(len=*), intent(in) :: words, sep
        integer :: i1, i2, nw
        n = 0
        nw = 0
        i2 = 0
        do
            call next_word(words, i2, i1)
            if (i1 == 0) exit
            nw = nw + 1
            n = n + i2 - i1 + 1
        end do
        n = n + len(sep)*max(0, nw - 1)
    end function commas_len

    !> The words joined by sep into s (of length commas_len(words, sep)).
    pure subroutine join_words(words, sep, s)
        character(len=*), intent(in) :: words, sep
        character(len=*), intent(out) :: s
        integer :: i1, i2, n
        n = 0
        i2 = 0
        do
            call next_word(words, i2, i1)
            if (i1 == 0) exit
            if (n > 0) then
                s(n + 1:n + len(sep)) = sep
                n = n + len(sep)
            end if
            s(n + 1:n + i2 - i1 + 1) = words(i1:i2)
            n = n + i2 - i1 + 1
        end do
    end subroutine join_words

    !> s for a message: at most CLIP_LEN characters, longer text cut with '...'.
    pure function clip(s) result(t)
        character(len=*), intent(in) :: s          !! any text
        character(len=min(len(s), CLIP_LEN)) :: t
        if (len(s) <= CLIP_LEN) then
            t = s
        else
            t = s(1:CLIP_LEN - 3)//'...'
        end if
    end function clip

    !> Quoted for namelist output, inner quotes doubled.
    pure function quoted(s) result(t)
        character(len=*), intent(in) :: s           !! text
        character(len=quoted_len(s)) :: t
        integer :: i, n
        t(1:1) = ''''
        n = 1
        do i = 1, len_trim(s)
            if (s(i:i) == '''') then
                t(n + 1:n + 2) = ''''''
                n = n + 2
            else
                t(n + 1:n + 1) = s(i:i)
                n = n + 1
            end if
        end do
        t(n + 1:n + 1) = ''''
    end function quoted

    !> The length of quoted(s).
    pure integer function quoted_len(s) result(n)
        character(len=*), intent(in) :: s           !! text
        integer :: i
        n = 2 + len_trim(s)
        do i = 1, len_trim(s)
            if (s(i:i) == '''') n = n + 1
        end do
    end function quoted_len

end module text
