!> Kind parameters and mathematical constants shared by every module of bifilar.
module kinds
    use, intrinsic :: iso_fortran_env, only: real64
    implicit none
    private

    integer, parameter, public :: dp = real64          !! double precision everywhere
    real(dp), parameter, public :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter, public :: deg = pi/180.0_dp   !! one degree in radians

end module kinds
