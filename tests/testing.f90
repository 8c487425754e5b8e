!> A small test harness: checks that count, print failures with both values, and a
!! closing line "N passed, N failed".
module testing
    use kinds, only: dp
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    type, public :: tester_t
        integer :: passed = 0
        integer :: failed = 0
        character(len=:), allocatable :: only   !! run only suites whose name contains this
    contains
        procedure :: check
        procedure :: check_close
        procedure :: want
        procedure :: summary
    end type tester_t

contains

    !> True when suite `name` is selected (no filter, or the filter is part of the name).
    logical function want(self, name)
        class(tester_t), intent(in) :: self
        character(len=*), intent(in) :: name
        want = .true.
        if (allocated(self%only)) then
            if (len_trim(self%only) > 0) want = index(name, trim(self%only)) > 0
        end if
        if (want) write (*, '(a)') '== '//name
    end function want

    !> Record a pass when cond holds, else a failure with its name.
    subroutine check(self, name, cond)
        class(tester_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        logical, intent(in) :: cond
        if (cond) then
            self%passed = self%passed + 1
        else
            self%failed = self%failed + 1
            write (*, '(a)') 'FAIL: '//name
        end if
    end subroutine check

    !> Pass when |actual - expected| <= atol + rtol*|expected| and both are finite.
    subroutine check_close(self, name, actual, expected, rtol, atol)
        class(tester_t), intent(inout) :: self
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: actual, expected
        real(dp), intent(in), optional :: rtol, atol
        real(dp) :: rt, at
        logical :: ok
        rt = 0.0_dp
        at = 0.0_dp
        if (present(rtol)) rt = rtol
        if (present(atol)) at = atol
        ok = ieee_is_finite(actual) .and. ieee_is_finite(expected)
        if (ok) ok = abs(actual - expected) <= at + rt*abs(expected)
        if (ok) then
            self%passed = self%passed + 1
        else
            self%failed = self%failed + 1
            write (*, '(a,es24.16,a,es24.16,a,es10.2,a,es10.2)') 'FAIL: '//name//': got ', &
                actual, ' expected ', expected, ' rtol ', rt, ' atol ', at
        end if
    end subroutine check_close

    !> Print the closing line; return .true. when nothing failed.
    logical function summary(self)
        class(tester_t), intent(in) :: self
        write (*, '(i0,a,i0,a)') self%passed, ' passed, ', self%failed, ' failed'
        summary = self%failed == 0
    end function summary

end module testing
