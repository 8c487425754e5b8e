!> Tests of module fast_format: its ESw.dE3 and Fw.d text against the run-time library's
!! formatted WRITE of the same value, character by character, over random bit patterns
!! (every magnitude, both signs, zeros, subnormals), infinities, exact decimal ties,
!! the neighbours of powers of ten, and the output grid of the data files.
module test_fast_format
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_negative_inf
    use kinds, only: dp
    use testing, only: tester_t
    use fast_format, only: es_field, f_field
    use text, only: itoa, sci, fixed, lead_zero
    use unused_arg, only: unused
    implicit none
    private

    public :: run_fast_format_tests

    integer, parameter :: i8 = selected_int_kind(18)

    !> Values compared, how many differ, the first that differs (format and library text).
    type :: tally_t
        integer :: cases = 0, bad = 0
        character(len=80) :: first = ''
    end type tally_t

contains

    subroutine run_fast_format_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call unused(exe)   ! every suite is given the executable; this one needs none
        if (t%want('fast_format: ES24.15E3 against the library')) call test_es(t)
        if (t%want('fast_format: F14.6 against the library')) call test_f(t)
        if (t%want('fast_format: other widths and digits')) call test_other(t)
        if (t%want('text: numbers in messages')) call test_text(t)
    end subroutine run_fast_format_tests

    !> Module text: integers without blanks, sci keeps its E at three-digit exponents,
    !! fixed and lead_zero put a zero before a leading point; non-finite values by name.
    subroutine test_text(t)
        type(tester_t), intent(inout) :: t
        real(dp) :: inf
        inf = ieee_value(1.0_dp, ieee_positive_inf)
        call t%check('itoa', itoa(0) == '0' .and. itoa(-7) == '-7' .and. &
                     itoa(huge(1)) == '2147483647')
        call t%check('sci: 1e300, -4.352e-14, 2.214, default 3 digits', &
                     sci(1.0e300_dp) == '1.000E+300' .and. sci(-4.352e-14_dp) == '-4.352E-14' &
                     .and. sci(2.214_dp) == '2.214E+00' .and. sci(0.5_dp, 1) == '5.0E-01')
        call t%check('sci: Inf, -Inf', sci(inf) == 'Inf' .and. sci(-inf) == '-Inf')
        call t%check('fixed: 0.05 -> 0.050000, -0.5 -> -0.50, 12 -> 12.0, 0 digits', &
                     fixed(0.05_dp, 6) == '0.050000' .and. fixed(-0.5_dp, 2) == '-0.50' .and. &
                     fixed(12.0_dp, 1) == '12.0' .and. fixed(2.6_dp, 0) == '3.')
        call t%check('fixed: -Inf, 1e116, 999999999.5', fixed(-inf, 3) == '-Inf' .and. &
                     fixed(1.0e116_dp, 6) == '1.000000E+116' .and. &
                     fixed(999999999.5_dp, 1) == '999999999.5')
        call t%check('lead_zero: .5, -.25, blanks, empty', lead_zero('  .5 ') == '0.5' .and. &
                     lead_zero('-.25') == '-0.25' .and. lead_zero(' 7 ') == '7' .and. &
                     lead_zero('   ') == '')
    end subroutine test_text

    !> es_field(x, 15) with a 24-character field against write (..., '(es24.15e3)').
    subroutine test_es(t)
        type(tester_t), intent(inout) :: t
        type(tally_t) :: tl
        real(dp) :: x, u(2)
        integer :: k, j
        call seed()
        ! random bit patterns: every exponent, subnormals included
        do k = 1, 20000
            call random_number(u)
            call compare(from_bits(u), .true., 24, 15, tl)
        end do
        ! random values of the magnitudes the data files hold (1e-20 ... 1e3)
        do k = 1, 20000
            call random_number(u)
            call compare((2*u(1) - 1)*10.0_dp**(23*u(2) - 20), .true., 24, 15, tl)
        end do
        ! exact binary fractions: i 2^-j has j decimals, so some of them are exact ties at
        ! the 16th significant digit (2^-24 = 5.9604644775390625e-8 -> ...062E-008)
        do j = 1, 80
            do k = 1, 41, 2
                call compare(k*2.0_dp**(-j), .true., 24, 15, tl)
                call compare(-k*2.0_dp**(-j), .true., 24, 15, tl)
            end do
        end do
        ! powers of ten and their neighbours (the decade chosen by the rounding)
        do j = -307, 308
            x = 10.0_dp**j
            call compare(x, .true., 24, 15, tl)
            call compare(nearest(x, 1.0_dp), .true., 24, 15, tl)
            call compare(nearest(x, -1.0_dp), .true., 24, 15, tl)
            call compare(-nearest(x, -1.0_dp), .true., 24, 15, tl)
        end do
        ! numbers that round up into the next decade, zeros, extremes, infinities
        call compare(9.9999999999999999e-5_dp, .true., 24, 15, tl)
        call compare(0.99999999999999994_dp, .true., 24, 15, tl)
        call compare(0.0_dp, .true., 24, 15, tl)
        call compare(-0.0_dp, .true., 24, 15, tl)
        call compare(huge(1.0_dp), .true., 24, 15, tl)
        call compare(-huge(1.0_dp), .true., 24, 15, tl)
        call compare(tiny(1.0_dp), .true., 24, 15, tl)
        call compare(nearest(tiny(1.0_dp), -1.0_dp), .true., 24, 15, tl)
        call compare(ieee_value(x, ieee_positive_inf), .true., 24, 15, tl)
        call compare(ieee_value(x, ieee_negative_inf), .true., 24, 15, tl)
        call report(t, 'ES24.15E3', tl, 40000)
    end subroutine test_es

    !> f_field(x, 6) with a 14-character field against write (..., '(f14.6)').
    subroutine test_f(t)
        type(tester_t), intent(inout) :: t
        type(tally_t) :: tl
        real(dp) :: x, u(2)
        integer :: k, j
        call seed()
        ! the output grid tau = k dtau_out of the data files
        do k = 0, 20000
            call compare(k*0.05_dp, .false., 14, 6, tl)
            call compare(k*0.001_dp, .false., 14, 6, tl)
            call compare(min(k*0.05_dp, 60.0_dp), .false., 14, 6, tl)
        end do
        ! random values up to beyond the field's width (asterisks) and tiny ones
        do k = 1, 20000
            call random_number(u)
            call compare((2*u(1) - 1)*10.0_dp**(16*u(2) - 9), .false., 14, 6, tl)
        end do
        do k = 1, 5000
            call random_number(u)
            call compare(from_bits(u), .false., 14, 6, tl)
        end do
        ! exact ties at the 6th decimal (2^-7 = 0.0078125 -> 0.007812) and near them
        do j = 1, 30
            do k = 1, 63, 2
                x = k*2.0_dp**(-j)
                call compare(x, .false., 14, 6, tl)
                call compare(-x, .false., 14, 6, tl)
                call compare(nearest(x, 1.0_dp), .false., 14, 6, tl)
                call compare(nearest(x, -1.0_dp), .false., 14, 6, tl)
            end do
        end do
        call compare(0.0_dp, .false., 14, 6, tl)
        call compare(-0.0_dp, .false., 14, 6, tl)
        call compare(-1.0e-9_dp, .false., 14, 6, tl)
        call compare(0.0000005_dp, .false., 14, 6, tl)
        call compare(0.0000025_dp, .false., 14, 6, tl)
        call compare(999999.9999995_dp, .false., 14, 6, tl)
        call compare(9999999.5_dp, .false., 14, 6, tl)
        call compare(-999999.9999996_dp, .false., 14, 6, tl)
        call report(t, 'F14.6', tl, 80000)
    end subroutine test_f

    !> Other widths and digit counts, including fields too narrow (the library's asterisks).
    subroutine test_other(t)
        type(tester_t), intent(inout) :: t
        type(tally_t) :: tl
        real(dp) :: u(2)
        integer :: k
        call seed()
        do k = 1, 6000
            call random_number(u)
            call compare((2*u(1) - 1)*10.0_dp**(40*u(2) - 20), .true., 8 + mod(k, 23), &
                         mod(k, 17), tl)
            call compare((2*u(1) - 1)*10.0_dp**(14*u(2) - 6), .false., 8 + mod(k, 23), &
                         1 + mod(k, 9), tl)
        end do
        call report(t, 'ESw.dE3 and Fw.d, w = 8 ... 30', tl, 12000)
    end subroutine test_other

    !> One value: our text against the library's, counted in tl.
    subroutine compare(x, es, w, d, tl)
        real(dp), intent(in) :: x
        logical, intent(in) :: es               !! ESw.dE3, else Fw.d
        integer, intent(in) :: w, d
        type(tally_t), intent(inout) :: tl
        character(len=w) :: ours, lib
        character(len=32) :: fmt
        if (es) then
            call es_field(x, d, ours)
            write (fmt, '(a,i0,a,i0,a)') '(es', w, '.', d, 'e3)'
        else
            call f_field(x, d, ours)
            write (fmt, '(a,i0,a,i0,a)') '(f', w, '.', d, ')'
        end if
        write (lib, fmt) x
        tl%cases = tl%cases + 1
        if (ours /= lib) then
            if (tl%bad == 0) tl%first = trim(fmt)//' ['//lib//']'
            tl%bad = tl%bad + 1
        end if
    end subroutine compare

    !> The check of one tally: no text differs, and at least `least` values were compared.
    subroutine report(t, what, tl, least)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: what
        type(tally_t), intent(in) :: tl
        integer, intent(in) :: least
        character(len=200) :: msg
        write (msg, '(a,i0,a,i0,a)') what//': ', tl%cases, ' values give the library''s '// &
            'text (', tl%bad, ' differ'
        if (tl%bad > 0) msg = trim(msg)//', first '//trim(tl%first)
        call t%check(trim(msg)//')', tl%bad == 0 .and. tl%cases >= least)
    end subroutine report

    !> A double from two uniform numbers taken as its two 32-bit halves; a NaN or infinity
    !! pattern (exponent bits all set) becomes the largest finite exponent instead (writing
    !! a signalling NaN would trap in the checking build; the formatter leaves non-finite
    !! values to the library anyway).
    function from_bits(u) result(x)
        real(dp), intent(in) :: u(2)
        real(dp) :: x
        integer(i8) :: hi, lo
        hi = int(u(1)*4294967296.0_dp, i8)
        lo = int(u(2)*4294967296.0_dp, i8)
        if (ibits(hi, 20, 11) == 2047) hi = ibclr(hi, 20)
        x = transfer(ior(shiftl(hi, 32), lo), x)
    end function from_bits

    !> The same random sequence on every run.
    subroutine seed()
        integer :: n
        integer, allocatable :: s(:)
        call random_seed(size=n)
        allocate (s(n))
        s = 20260 + 7*[(n, n=1, size(s))]
        call random_seed(put=s)
    end subroutine seed

end module test_fast_format
