!> Numbers as text for messages and headers: integers without blanks, reals in scientific
!! notation that always keeps its E (a plain `es10.3` prints 1e300 as `1.000+300`, which
!! no reader takes for a number).
module text
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use kinds, only: dp
    implicit none
    private

    public :: itoa, sci, fixed, lead_zero

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

end module text
