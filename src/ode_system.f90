!> The abstract right-hand side every integration in bifilar works on.
!!
!! A problem extends ode_system with its own data (lengths, masses, counters) and
!! implements rhs; it may also override jacobian and has_jacobian to give an analytic
!! Jacobian.  The integrator (module lsoda) sees only this type.
module ode_system
    use kinds, only: dp
    use status, only: status_t
    implicit none
    private

    type, abstract, public :: ode_system_t
    contains
        procedure(rhs_i), deferred :: rhs
        procedure :: jacobian => no_jacobian
        procedure :: has_jacobian => no_jacobian_given
    end type ode_system_t

    abstract interface
        !> ydot = f(t, y).  stat%code /= 0 stops the integration with that status.
        subroutine rhs_i(sys, t, y, ydot, stat)
            import :: ode_system_t, dp, status_t
            class(ode_system_t), intent(inout) :: sys
            real(dp), intent(in) :: t        !! independent variable
            real(dp), intent(in) :: y(:)     !! state
            real(dp), intent(out) :: ydot(:) !! derivative of the state
            type(status_t), intent(out) :: stat
        end subroutine rhs_i
    end interface

contains

    !> Default Jacobian: none.  Only called when has_jacobian() is .true.
    subroutine no_jacobian(sys, t, y, dfdy, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t            !! independent variable
        real(dp), intent(in) :: y(:)         !! state
        real(dp), intent(out) :: dfdy(:, :)  !! df_i/dy_j
        type(status_t), intent(out) :: stat
        if (.false.) call sys%rhs(t, y, dfdy(:, 1), stat)   ! keep arguments referenced
        dfdy = 0.0_dp
        stat%code = 0
    end subroutine no_jacobian

    !> Default: no analytic Jacobian; the integrator uses finite differences.
    logical function no_jacobian_given(sys)
        class(ode_system_t), intent(in) :: sys
        no_jacobian_given = .false.
        if (.false.) no_jacobian_given = same_type_as(sys, sys)
    end function no_jacobian_given

end module ode_system
