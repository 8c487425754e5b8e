!> The two abstract types every integration in bifilar goes through: the right-hand side
!! (ode_system_t) and the integrator (integrator_t, with one statistics type).
!!
!! The right-hand side.  A problem extends ode_system with its own data (lengths, masses, counters) and
!! implements rhs; it may also override jacobian and has_jacobian to give an analytic
!! Jacobian.  The integrator (module lsoda) sees only this type.
!!
!! A problem whose Jacobian has a structure (e.g. block diagonal with identical blocks, as
!! the variational equations of module floquet) may also solve the stiff method's linear
!! systems itself: it overrides has_iteration_solver to return .true., factor_iteration to
!! form and factor P = I - h l0 J at (t, y) in its own storage, and solve_iteration to
!! replace x by P^-1 x.  The integrator then never forms the n x n matrix; its counts
!! (Jacobian evaluations, factorisations) are kept as for the dense path.
!!
!! The integrator.  An abstract type that the project's integrators extend (LSODA, module
!! lsoda; Radau IIA, module radau), with one statistics type.  A driver holds a `class(integrator_t), allocatable` made by module
!! integrators (new_integrator) and never asks which integrator it is, except for the name
!! it writes into its output.
!!
!! The calls:
!! - init(sys, t0, y0, rtol, atol, stat [, tcrit, h0, hmax, max_steps]): start at (t0, y0);
!!   atol of size 1 or n; no step goes past tcrit; h0 the first step to try (else
!!   estimated); hmax the largest step; max_steps the most steps in one call of integrate;
!! - step(sys, stat [, tout]): one internal step (tout before the first: direction, scale);
!! - integrate(sys, tout, y, stat): steps up to tout and the solution there;
!! - dense(t, k, dky, stat): the solution (k = 0) or its derivative (k = 1) at t inside the
!!   last step;
!! - stats(): the counters (integrator_stats_t);
!! - set_tcrit([tcrit], [stat]): set or remove the stop time;
!! - name(): 'lsoda' or 'radau';
!! - sens_init(sys, s0, stat [, scale, error_control]): forward sensitivities from s0 (n x ns)
!!   along with the state (below); sens_dense(t, k, ds, stat): them (k = 0) or their
!!   derivative (k = 1) at t inside the last step; sens_dense_dot(t, g, v, stat): g . s_k
!!   for each column at t, when a linear function of the state is all a caller needs.
!! Failures come back in status_t with the integrator's codes of status's STATUS_TABLE.
!!
!! Forward sensitivities.  After init and before the first step, sens_init starts ns
!! sensitivities s_k = dy/dp_k with s_k(t0) = s0(:, k); they follow
!!     s_k' = J(t, y) s_k + df/dp_k(t, y)
!! by the staggered direct method (Caracotsios & Stewart 1985; Maly & Petzold 1996): once a
!! step's state has converged, the same formula is solved for the sensitivities at the new
!! point, reusing the step's iteration (LSODA: the Newton matrix of a BDF step, the
!! functional iteration of an Adams step; Radau IIA: the step's factored matrices).  The
!! state's steps are not changed by them: the sensitivities take no part in the error
!! control unless sens_init asks for it (error_control = .true.).  The system gives the
!! terms through sens_point (df/dp at a point; default 0, sensitivities of the initial
!! conditions only), sens_jv (products J v at that point; default from the analytic
!! Jacobian, else forward differences of the right-hand side) and sens_jacobian (J itself
!! there; default the products with the columns of I).
module ode_system
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC, LSODA_ERR_TOO_MUCH_ACCURACY, RADAU_ERR_TOO_MUCH_ACCURACY, &
        RADAU_ERR_STEP_TOO_SMALL
    use unused_arg, only: unused
    implicit none
    private

    type, abstract, public :: ode_system_t
        !> the Jacobian of the default sens_point (sens_jv multiplies with it)
        real(dp), allocatable, private :: sens_jac(:, :)
    contains
        procedure(rhs_i), deferred :: rhs
        procedure :: jacobian => no_jacobian
        procedure :: has_jacobian => no_jacobian_given
        procedure :: has_iteration_solver => no_iteration_solver_given
        procedure :: factor_iteration => no_factor_iteration
        procedure :: solve_iteration => no_solve_iteration
        procedure :: sens_point => default_sens_point
        procedure :: sens_jv => default_sens_jv
        procedure :: sens_jacobian => default_sens_jacobian
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

    !> The method of a step (integrator_stats_t method_last, method_next).
    integer, parameter, public :: METHOD_ADAMS = 1   !! non-stiff method (Adams-Moulton)
    integer, parameter, public :: METHOD_BDF = 2     !! stiff method (backward differentiation)
    integer, parameter, public :: METHOD_RADAU = 3   !! Radau IIA, order 5

    !> Counters and the state of the method, as returned by integrator_t%stats().
    type, public :: integrator_stats_t
        integer :: steps = 0            !! accepted steps since init
        integer :: rhs_evals = 0        !! calls of sys%rhs (including finite-difference Jacobians)
        integer :: jac_evals = 0        !! Jacobian evaluations (analytic or finite differences)
        integer :: lu_decomps = 0       !! LU factorisations of the iteration matrix (Radau: the
                                        !! real and the complex one count 1)
        integer :: conv_failures = 0    !! step attempts rejected: the corrector (Newton)
                                        !! iteration did not converge
        integer :: error_test_failures = 0  !! step attempts rejected by the local error test
        integer :: newton_iterations = 0    !! Radau: simplified Newton iterations
        integer :: method_switches = 0  !! LSODA: switches Adams <-> BDF
        integer :: sens_points = 0      !! points where the sensitivity terms were taken
                                        !! (sens_point: one per step, Radau three)
        integer :: sens_iterations = 0  !! iterations of the sensitivities' corrector
        integer :: sens_direct = 0      !! sensitivity solves with a new factorisation
        integer :: method_last = 0      !! METHOD_ADAMS, METHOD_BDF or METHOD_RADAU, last step
        integer :: order_last = 0       !! order used on the last step
        integer :: method_next = 0      !! method to be tried on the next step
        integer :: order_next = 0       !! order to be tried on the next step
        real(dp) :: h_last = 0.0_dp     !! last step size taken (signed)
        real(dp) :: h_next = 0.0_dp     !! step size to be tried next (signed)
        real(dp) :: t_current = 0.0_dp  !! time reached by the integration (end of last step)
    end type integrator_stats_t

    !> One integration by one of the project's integrators.
    type, abstract, public :: integrator_t
    contains
        procedure(init_i), deferred :: init
        procedure(integrate_i), deferred :: integrate
        procedure(step_i), deferred :: step
        procedure(dense_i), deferred :: dense
        procedure(stats_i), deferred :: stats
        procedure(set_tcrit_i), deferred :: set_tcrit
        procedure(name_i), deferred :: name
        procedure(sens_init_i), deferred :: sens_init
        procedure(sens_dense_i), deferred :: sens_dense
        procedure :: sens_dense_dot => default_sens_dense_dot
    end type integrator_t

    abstract interface
        !> Start an integration at (t0, y0).
        subroutine init_i(s, sys, t0, y0, rtol, atol, stat, tcrit, h0, hmax, max_steps)
            import :: integrator_t, ode_system_t, dp, status_t
            class(integrator_t), intent(inout) :: s
            class(ode_system_t), intent(inout) :: sys
            real(dp), intent(in) :: t0                  !! initial time
            real(dp), intent(in) :: y0(:)               !! initial state (size n >= 1)
            real(dp), intent(in) :: rtol                !! relative tolerance
            real(dp), intent(in) :: atol(:)             !! absolute tolerance, size 1 or n
            type(status_t), intent(out) :: stat
            real(dp), intent(in), optional :: tcrit     !! no step goes past tcrit
            real(dp), intent(in), optional :: h0        !! first step to try
            real(dp), intent(in), optional :: hmax      !! largest |h| (> 0)
            integer, intent(in), optional :: max_steps  !! most steps in one call of integrate
        end subroutine init_i
        !> Steps up to tout and the solution there.
        subroutine integrate_i(s, sys, tout, y, stat)
            import :: integrator_t, ode_system_t, dp, status_t
            class(integrator_t), intent(inout) :: s
            class(ode_system_t), intent(inout) :: sys
            real(dp), intent(in) :: tout
            real(dp), intent(out) :: y(:)
            type(status_t), intent(out) :: stat
        end subroutine integrate_i
        !> One internal step.
        subroutine step_i(s, sys, stat, tout)
            import :: integrator_t, ode_system_t, dp, status_t
            class(integrator_t), intent(inout) :: s
            class(ode_system_t), intent(inout) :: sys
            type(status_t), intent(out) :: stat
            real(dp), intent(in), optional :: tout      !! before the first step: direction
        end subroutine step_i
        !> The solution (k = 0) or its derivative (k = 1) at t in the last step.
        subroutine dense_i(s, t, k, dky, stat)
            import :: integrator_t, dp, status_t
            class(integrator_t), intent(in) :: s
            real(dp), intent(in) :: t
            integer, intent(in) :: k
            real(dp), intent(out) :: dky(:)
            type(status_t), intent(out) :: stat
        end subroutine dense_i
        !> The counters.
        function stats_i(s) result(st)
            import :: integrator_t, integrator_stats_t
            class(integrator_t), intent(in) :: s
            type(integrator_stats_t) :: st
        end function stats_i
        !> Set (tcrit present) or remove (absent) the stop time.
        subroutine set_tcrit_i(s, tcrit, stat)
            import :: integrator_t, dp, status_t
            class(integrator_t), intent(inout) :: s
            real(dp), intent(in), optional :: tcrit
            type(status_t), intent(out), optional :: stat
        end subroutine set_tcrit_i
        !> The integrator's name as written in output files: 'lsoda' or 'radau'.
        pure function name_i(s) result(nm)
            import :: integrator_t
            class(integrator_t), intent(in) :: s
            character(len=:), allocatable :: nm
        end function name_i
    end interface

    abstract interface
        !> Start forward sensitivities (after init, before the first step).
        subroutine sens_init_i(s, sys, s0, stat, scale, error_control)
            import :: integrator_t, ode_system_t, dp, status_t
            class(integrator_t), intent(inout) :: s
            class(ode_system_t), intent(inout) :: sys
            real(dp), intent(in) :: s0(:, :)            !! (n, ns) dy(t0)/dp_k
            type(status_t), intent(out) :: stat
            real(dp), intent(in), optional :: scale(:)  !! (ns) the size of column k
                                                        !! against the state's (atol x scale)
            logical, intent(in), optional :: error_control  !! in the error test (default no)
        end subroutine sens_init_i
        !> The sensitivities (k = 0) or their derivative (k = 1) at t in the last step.
        subroutine sens_dense_i(s, t, k, ds, stat)
            import :: integrator_t, dp, status_t
            class(integrator_t), intent(in) :: s
            real(dp), intent(in) :: t
            integer, intent(in) :: k
            real(dp), intent(out) :: ds(:, :)           !! (n, ns)
            type(status_t), intent(out) :: stat
        end subroutine sens_dense_i
    end interface

    public :: too_much_accuracy, default_sens_point, sens_init_args, default_sens_dense_dot

contains

    !> v(k) = g . s_k(t), the projection of each sensitivity on g at t inside the last step
    !! (default: from sens_dense; an integrator may form it from its own representation).
    !!
    !! g    [in]  (n) the vector.
    !! v    [out] (ns) the projections.
    !! stat [out] as sens_dense.
    subroutine default_sens_dense_dot(s, t, g, v, stat)
        class(integrator_t), intent(in) :: s
        real(dp), intent(in) :: t
        real(dp), intent(in) :: g(:)
        real(dp), intent(out) :: v(:)
        type(status_t), intent(out) :: stat
        real(dp) :: ds(size(g), size(v))
        integer :: k
        call s%sens_dense(t, 0, ds, stat)
        do k = 1, size(v)
            v(k) = dot_product(g, ds(:, k))
        end do
    end subroutine default_sens_dense_dot

    !> The checks every integrator's sens_init makes of its arguments: called after init
    !! and before the first step (ready, not started), s0 of n rows and ns >= 1 columns,
    !! scale (when given) ns entries each > 0.  On success sc is the scales (default 1) and
    !! stat is OK; else stat carries `code` and a message that starts with `who`.
    subroutine sens_init_args(who, code, ready, started, n, s0, sc, stat, scale)
        character(len=*), intent(in) :: who        !! 'lsoda sens_init', 'radau sens_init'
        integer, intent(in) :: code                 !! the integrator's illegal-input code
        logical, intent(in) :: ready, started       !! init done, a step taken
        integer, intent(in) :: n                    !! the state's size
        real(dp), intent(in) :: s0(:, :)            !! the sensitivities' start (n x ns)
        real(dp), intent(out) :: sc(:)              !! (ns) the scales
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: scale(:)  !! (ns) as given to sens_init
        integer :: ns
        stat%code = 0
        ns = size(s0, 2)
        sc = 1.0_dp
        if (.not. ready .or. started) then
            call set_error(stat, code, who//': after init and before the first step only')
        else if (size(s0, 1) /= n .or. ns < 1) then
            call set_error(stat, code, who//': s0 must be n x ns, ns >= 1')
        else if (present(scale)) then
            if (size(scale) /= ns .or. .not. all(scale > 0.0_dp)) then
                call set_error(stat, code, who//': scale must have ns entries, each > 0')
            else
                sc = scale
            end if
        end if
    end subroutine sens_init_args

    !> Default Jacobian: none.  Only called when has_jacobian() is .true.
    subroutine no_jacobian(sys, t, y, dfdy, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t            !! independent variable
        real(dp), intent(in) :: y(:)         !! state
        real(dp), intent(out) :: dfdy(:, :)  !! df_i/dy_j
        type(status_t), intent(out) :: stat
        call unused(sys)
        call unused(t)
        call unused(y)
        dfdy = 0.0_dp
        stat%code = 0
    end subroutine no_jacobian

    !> Default: no analytic Jacobian; the integrator uses finite differences.
    logical function no_jacobian_given(sys)
        class(ode_system_t), intent(in) :: sys
        call unused(sys)
        no_jacobian_given = .false.
    end function no_jacobian_given

    !> Default: the integrator forms and factors the iteration matrix itself.
    logical function no_iteration_solver_given(sys)
        class(ode_system_t), intent(in) :: sys
        call unused(sys)
        no_iteration_solver_given = .false.
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
        call unused(sys)
        call unused(t)
        call unused(y)
        call unused(hl0)
        call unused(rewt)
        jnorm = 0.0_dp
        singular = .false.
        stat%code = 0
    end subroutine no_factor_iteration

    !> x := P^-1 x with the factors of factor_iteration.  Only called when
    !! has_iteration_solver() is .true.; this default does nothing.
    subroutine no_solve_iteration(sys, x, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(inout) :: x(:)          !! right-hand side; on return the solution
        type(status_t), intent(out) :: stat
        call unused(sys)
        call unused(x)
        stat%code = 0
    end subroutine no_solve_iteration

    !> Default sensitivity terms at (t, y): df/dp = 0 (the sensitivities of the initial
    !! conditions: the variational equations), and J(t, y) for sens_jv: the analytic Jacobian
    !! when the system has one, else forward differences of the right-hand side (increments
    !! sqrt(eps) max(|y_j|, 1e-5)).  Public, so that a system's own sens_point can take its
    !! Jacobian from here and add its df/dp.
    subroutine default_sens_point(sys, t, y, dfdp, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t                !! independent variable
        real(dp), intent(in) :: y(:)             !! state
        real(dp), intent(out) :: dfdp(:, :)      !! (n, ns) df/dp_k at (t, y)
        type(status_t), intent(out) :: stat
        real(dp) :: f0(size(y)), f1(size(y)), yj(size(y)), del
        integer :: n, j
        n = size(y)
        dfdp = 0.0_dp
        if (allocated(sys%sens_jac)) then
            if (size(sys%sens_jac, 1) /= n) deallocate (sys%sens_jac)
        end if
        if (.not. allocated(sys%sens_jac)) allocate (sys%sens_jac(n, n))
        if (sys%has_jacobian()) then
            call sys%jacobian(t, y, sys%sens_jac, stat)
            return
        end if
        call sys%rhs(t, y, f0, stat)
        if (stat%code /= 0) return
        yj = y
        do j = 1, n
            del = sqrt(epsilon(1.0_dp))*max(abs(y(j)), 1.0e-5_dp)
            yj(j) = y(j) + del
            del = yj(j) - y(j)
            call sys%rhs(t, yj, f1, stat)
            if (stat%code /= 0) return
            sys%sens_jac(:, j) = (f1 - f0)/del
            yj(j) = y(j)
        end do
    end subroutine default_sens_point

    !> Default products jv = J v with the Jacobian of the last sens_point.
    subroutine default_sens_jv(sys, v, jv, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: v(:, :)          !! (n, m)
        real(dp), intent(out) :: jv(:, :)        !! (n, m)
        type(status_t), intent(out) :: stat
        stat%code = 0
        if (.not. allocated(sys%sens_jac)) then
            jv = 0.0_dp
            call set_error(stat, ERR_NUMERIC, 'sensitivities: sens_jv before sens_point')
            return
        end if
        jv = matmul(sys%sens_jac, v)
    end subroutine default_sens_jv

    !> Default J at the point of the last sens_point: the products with I's columns.
    subroutine default_sens_jacobian(sys, jac, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(out) :: jac(:, :)       !! (n, n)
        type(status_t), intent(out) :: stat
        real(dp) :: eye(size(jac, 1), size(jac, 1))
        integer :: i
        eye = 0.0_dp
        do i = 1, size(jac, 1)
            eye(i, i) = 1.0_dp
        end do
        call sys%sens_jv(eye, jac, stat)
    end subroutine default_sens_jacobian

    !> True when stat is an integrator's refusal of a tolerance below what the machine
    !! precision allows (LSODA), or a step size that fell below the roundoff of t (Radau).
    pure logical function too_much_accuracy(stat)
        type(status_t), intent(in) :: stat
        too_much_accuracy = stat%code == LSODA_ERR_TOO_MUCH_ACCURACY .or. &
                            stat%code == RADAU_ERR_TOO_MUCH_ACCURACY .or. &
                            stat%code == RADAU_ERR_STEP_TOO_SMALL
    end function too_much_accuracy

end module ode_system
