!> The one idiom for a dummy argument that an interface imposes and a procedure does not
!! need (a right-hand side that does not depend on t, a default binding that ignores the
!! system, an analysis without sweeps given the sweep options):
!!
!!     call unused(t)
!!
!! `unused` does nothing.  The call references the argument, so gfortran's
!! -Wunused-dummy-argument (of -Wall -Wextra) stays quiet for that argument alone and keeps
!! watching every other, and the reader sees at the top of the procedure which arguments
!! it ignores.  It takes any type (class(*)): a scalar, present or an absent optional one,
!! or an array of rank 1 or 2; it is pure (usable in pure procedures) and empty (the
!! optimised build removes the call).  An intent(out) argument is not silenced this way:
!! it is given its value.
module unused_arg
    implicit none
    private

    public :: unused

    !> Reference an argument and do nothing.
    interface unused
        module procedure unused_scalar, unused_rank1, unused_rank2
    end interface unused

contains

    ! Each body is an empty select type: it references x (the one place the no-op needs to)
    ! and selects nothing.

    !> A scalar of any type, an absent optional one too.
    pure subroutine unused_scalar(x)
        class(*), intent(in), optional :: x         !! the argument not needed
        if (present(x)) then
            select type (x)
            end select
        end if
    end subroutine unused_scalar

    !> An array of rank 1 of any type.
    pure subroutine unused_rank1(x)
        class(*), intent(in) :: x(:)                !! the argument not needed
        select type (x)
        end select
    end subroutine unused_rank1

    !> An array of rank 2 of any type.
    pure subroutine unused_rank2(x)
        class(*), intent(in) :: x(:, :)             !! the argument not needed
        select type (x)
        end select
    end subroutine unused_rank2

end module unused_arg
