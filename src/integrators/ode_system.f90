!> The abstract right-hand side every integration in bifilar works on.
!!
!! A problem extends ode_system with its own data (lengths, masses, counters) and
!! implements rhs; it may also override jacobian and has_jacobian to give an analytic
!! Jacobian.  The integrator (module lsoda) sees only this type.
!!
!! A problem whose Jacobian has a structure (e.g. block diagonal with identical blocks, as
!! the variational equations of module floquet) may also solve the stiff method's linear
!! systems itself: it overrides has_iteration_solver to return .true., factor_iteration to
!! form and factor P = I - h l0 J at (t, y) in its own storage, and solve_iteration to
!! replace x by P^-1 x.  The integrator then never forms the n x n matrix; its counts
!! (Jacobian evaluations, factorisations) are kept as for the dense path.
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
        procedure :: has_iteration_solver => no_iteration_solver_given
        procedure :: factor_iteration => no_factor_iteration
        procedure :: solve_iteration => no_solve_iteration
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

    !> Default: the integrator forms and factors the iteration matrix itself.
    logical function no_iteration_solver_given(sys)
        class(ode_system_t), intent(in) :: sys
        no_iteration_solver_given = .false.
        if (.false.) no_iteration_solver_given = same_type_as(sys, sys)
    end function no_iteration_solver_given

    !> Form and factor P = I - hl0 J(t, y) for the chord iteration of the stiff method, and
    !! return the norm of J the method switching uses.  Only called when
    !! has_iteration_solver() is .true.; this default does nothing.
    subroutine no_factor_iteration(sys, t, y, hl0, rewt, jnorm, singular, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t                !! independent variable
        real(dp), intent(in) :: y(:)             !! state (the predicted solution)
        real(dp), intent(in) :: hl0              !! h l0 of the method
        real(dp), intent(in) :: rewt(:)          !! reciprocal error weights 1/w_i
        real(dp), intent(out) :: jnorm           !! max_i w_i^-1 sum_j |J_ij| w_j
        logical, intent(out) :: singular         !! P is singular (not factored)
        type(status_t), intent(out) :: stat      !! a failure of the Jacobian's evaluation
        jnorm = 0.0_dp
        singular = .false.
        if (.false.) jnorm = t + y(1) + hl0 + rewt(1)     ! keep arguments referenced
        if (.false.) singular = same_type_as(sys, sys)
        stat%code = 0
    end subroutine no_factor_iteration

    !> x := P^-1 x with the factors of factor_iteration.  Only called when
    !! has_iteration_solver() is .true.; this default does nothing.
    subroutine no_solve_iteration(sys, x, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(inout) :: x(:)          !! right-hand side; on return the solution
        type(status_t), intent(out) :: stat
        stat%code = 0
        if (.false.) x(1) = 0.0_dp                         ! keep arguments referenced
        if (.false.) stat%code = merge(1, 0, same_type_as(sys, sys))
    end subroutine no_solve_iteration

end module ode_system
