!> Vector algebra in three dimensions shared by the models.
module vectors
    use kinds, only: dp
    implicit none
    private

    public :: cross

contains

    !> The cross product a x b.
    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c(1) = a(2)*b(3) - a(3)*b(2)
        c(2) = a(3)*b(1) - a(1)*b(3)
        c(3) = a(1)*b(2) - a(2)*b(1)
    end function cross

end module vectors
