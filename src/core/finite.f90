!> Whether a double is finite, from its bits alone (its exponent is not all ones), for
!! values that come from outside, such as a checkpoint's: ieee_is_finite and every
!! comparison trap on a signalling NaN in the checking build.  (Apart from fptraps, which
!! the lowest text formatting uses and which needs no kind.)
module finite
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    implicit none
    private

    public :: finite_bits

contains

    !> x is finite (neither Inf nor NaN), decided from its bits without an operation that
    !! could trap.
    pure elemental logical function finite_bits(x)
        real(dp), intent(in) :: x                   !! the value
        finite_bits = iand(shiftr(transfer(x, 0_int64), 52), 2047_int64) /= 2047_int64
    end function finite_bits

end module finite
