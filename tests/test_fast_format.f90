!> Tests of module fast_format: its ESw.dE3 and Fw.d text against the run-time library's
!! formatted WRITE of the same value, character by character, over random bit patterns
!! (every magnitude, both signs, zeros, subnormals), infinities, exact decimal ties,
!! the neighbours of powers of ten, and the output grid of the data files.
module test_fast_format
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_negative_inf
    use kinds, only: dp
    use testing, only: tester_t
    use fast_format, only: es_field, f_field
    implicit none
    private

    public :: run_fast_format_tests

    integer, parameter :: i8 = selected_int_kind(18)

contains

    subroutine run_fast_format_tests(t)
        type(tester_t), intent(inout) :: t
        if (t%want('fast_format: ES24.15E3 against the library')) call test_es(t)
        if (t%want('fast_format: F14.6 against the library')) call test_f(t)
        if (t%want('fast_format: other widths and digits')) call test_other(t)
    end subroutine run_fast_format_tests

    !> es_field(x, 15) with a 24-character field against write (..., '(es24.15e3)').
    subroutine test_es(t)
        type(tester_t), intent(inout) :: t
        real(dp) :: x, u(2)
        integer :: k, j, nbad, ncase
        character(len=24) :: first_bad
        nbad = 0
        ncase = 0
        first_bad = ''
        call seed()
        ! random bit patterns: every exponent, subnormals included
        do k = 1, 20000
            call random_number(u)
            x = from_bits(u)
            call one(x)
        end do
        ! random values of the magnitudes the data files hold (1e-20 ... 1e3)
        do k = 1, 20000
            call random_number(u)
            x = (2*u(1) - 1)*10.0_dp**(23*u(2) - 20)
            call one(x)
        end do
        ! exact binary fractions: i 2^-j has j decimals, so some of them are exact ties at
        ! the 16th significant digit (2^-24 = 5.9604644775390625e-8 -> ...062E-008)
        do j = 1, 80
            do k = 1, 41, 2
                call one(k*2.0_dp**(-j))
                call one(-k*2.0_dp**(-j))
            end do
        end do
        ! powers of ten and their neighbours (the decade chosen by the rounding)
        do j = -307, 308
            x = 10.0_dp**j
            call one(x)
            call one(nearest(x, 1.0_dp))
            call one(nearest(x, -1.0_dp))
            call one(-nearest(x, -1.0_dp))
        end do
        ! numbers that round up into the next decade, zeros, extremes
        call one(9.9999999999999999e-5_dp)
        call one(0.99999999999999994_dp)
        call one(0.0_dp)
        call one(-0.0_dp)
        call one(huge(1.0_dp))
        call one(-huge(1.0_dp))
        call one(tiny(1.0_dp))
        call one(nearest(tiny(1.0_dp), -1.0_dp))
        call one(ieee_value(x, ieee_positive_inf))
        call one(ieee_value(x, ieee_negative_inf))
        call t%check('ES24.15E3: '//itoa(ncase)//' values give the library''s text ('// &
                     itoa(nbad)//' differ'//trim(first_bad)//')', nbad == 0 .and. ncase > 40000)
    contains
        subroutine one(v)
            real(dp), intent(in) :: v
            character(len=24) :: ours, lib
            call es_field(v, 15, ours)
            write (lib, '(es24.15e3)') v
            ncase = ncase + 1
            if (ours /= lib) then
                if (nbad == 0) first_bad = ': '//lib(1:len(first_bad) - 2)
                nbad = nbad + 1
            end if
        end subroutine one
    end subroutine test_es

    !> f_field(x, 6) with a 14-character field against write (..., '(f14.6)').
    subroutine test_f(t)
        type(tester_t), intent(inout) :: t
        real(dp) :: x, u(2)
        integer :: k, j, nbad, ncase
        character(len=14) :: first_bad
        nbad = 0
        ncase = 0
        first_bad = ''
        call seed()
        ! the output grid tau = k dtau_out of the data files
        do k = 0, 20000
            call one(k*0.05_dp)
            call one(k*0.001_dp)
            call one(min(k*0.05_dp, 60.0_dp))
        end do
        ! random values up to beyond the field's width (asterisks) and tiny ones
        do k = 1, 20000
            call random_number(u)
            x = (2*u(1) - 1)*10.0_dp**(16*u(2) - 9)
            call one(x)
        end do
        do k = 1, 5000
            call random_number(u)
            call one(from_bits(u))
        end do
        ! exact ties at the 6th decimal (2^-7 = 0.0078125 -> 0.007812) and near them
        do j = 1, 30
            do k = 1, 63, 2
                x = k*2.0_dp**(-j)
                call one(x)
                call one(-x)
                call one(nearest(x, 1.0_dp))
                call one(nearest(x, -1.0_dp))
            end do
        end do
        call one(0.0_dp)
        call one(-0.0_dp)
        call one(-1.0e-9_dp)
        call one(0.0000005_dp)
        call one(0.0000025_dp)
        call one(999999.9999995_dp)
        call one(9999999.5_dp)
        call one(-999999.9999996_dp)
        call t%check('F14.6: '//itoa(ncase)//' values give the library''s text ('// &
                     itoa(nbad)//' differ'//trim(first_bad)//')', nbad == 0 .and. ncase > 80000)
    contains
        subroutine one(v)
            real(dp), intent(in) :: v
            character(len=14) :: ours, lib
            call f_field(v, 6, ours)
            write (lib, '(f14.6)') v
            ncase = ncase + 1
            if (ours /= lib) then
                if (nbad == 0) first_bad = ': '//lib(1:len(first_bad) - 2)
                nbad = nbad + 1
            end if
        end subroutine one
    end subroutine test_f

    !> Other widths and digit counts, including fields too narrow (the library's asterisks).
    subroutine test_other(t)
        type(tester_t), intent(inout) :: t
        real(dp) :: x, u(2)
        integer :: k, nbad, ncase, w, d
        character(len=40) :: ours, lib, fmt
        nbad = 0
        ncase = 0
        call seed()
        do k = 1, 6000
            call random_number(u)
            x = (2*u(1) - 1)*10.0_dp**(40*u(2) - 20)
            w = 8 + mod(k, 23)
            d = mod(k, 17)
            write (fmt, '(a,i0,a,i0,a)') '(es', w, '.', d, 'e3)'
            call es_field(x, d, ours(1:w))
            write (lib(1:w), fmt) x
            ncase = ncase + 1
            if (ours(1:w) /= lib(1:w)) nbad = nbad + 1
            d = 1 + mod(k, 9)
            x = (2*u(1) - 1)*10.0_dp**(14*u(2) - 6)
            write (fmt, '(a,i0,a,i0,a)') '(f', w, '.', d, ')'
            call f_field(x, d, ours(1:w))
            write (lib(1:w), fmt) x
            ncase = ncase + 1
            if (ours(1:w) /= lib(1:w)) nbad = nbad + 1
        end do
        call t%check('ESw.dE3 and Fw.d, w = 8 ... 30: '//itoa(ncase)//' values give the '// &
                     'library''s text ('//itoa(nbad)//' differ)', nbad == 0)
    end subroutine test_other

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

    pure function itoa(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function itoa

end module test_fast_format
