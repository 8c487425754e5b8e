!> The two abstract types every integration in bifilar goes through: the right-hand side
!! (ode_system_t) and the integrator (integrator_t, with one statistics type).
!!
!! The right-hand side.  A problem extends ode_system_t with its own data (lengths, masses,
!! counters) and implements rhs; it may also override jacobian and has_jacobian to give an
!! analytic Jacobian.  The integrators (modules lsoda and radau) see only this type.
!!
!! A problem whose Jacobian has a structure (e.g. block diagonal with identical blocks, as
!! the variational equations of module floquet) may also solve the stiff method's linear
!! systems itself: it overrides has_iteration_solver to return .true., factor_iteration to
!! form and factor P = I - h l0 J at (t, y) in its own storage, and solve_iteration to
!! replace x by P^-1 x.  The integrator then never forms the n x n matrix; its counts
!! (Jacobian evaluations, factorisations) are kept as for the dense path.
!!
!! The integrator.  An abstract type that the project's integrators extend (LSODA, module
!! lsoda; Radau IIA, module radau), with one statistics type.  A driver holds a
!! `class(integrator_t), allocatable` made by module integrators (new_integrator) and never
!! asks which integrator it is, except for the name it writes into its output.
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
!!
!! What integrator_t holds for every integrator (as SciPy's OdeSolver holds t and the
!! counters, and each method writes its step): the state and counters they all keep (n, the
!! tolerances, t, h, the last step hu, tcrit, the counters, the sensitivities' number and
!! tolerances), the checks of the arguments they all take (init_common, sens_init_common,
!! check_in_step, and those of integrate, step, dense, sens_dense and set_tcrit), and
!! integrate and step themselves, which drive the integrator's own parts: identity (its
!! name and status codes), start (the first step size), one_step (one accepted step),
!! solution (the solution at t), at_tcrit, dense_at and sens_dense_at (its dense output).
!! The components are public, for the extensions in other modules: only the integrators'
!! procedures write them; a driver reads an integration through stats() and dense().
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
    use status, only: status_t, set_error, STATUS_OK, ERR_NUMERIC, &
        LSODA_ERR_TOO_MUCH_ACCURACY, RADAU_ERR_TOO_MUCH_ACCURACY, RADAU_ERR_STEP_TOO_SMALL
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

    !> The most steps one call of integrate takes unless init is told otherwise.
    integer, parameter, public :: DEFAULT_MAX_STEPS = 500000

    !> What an integrator is to the procedures of integrator_t: its name and the status codes
    !! with which it answers (its own of status's STATUS_TABLE).
    type, public :: integrator_id_t
        character(len=8) :: name = ''   !! as written in output files: 'lsoda' or 'radau'
        integer :: illegal_input = 0    !! code of a bad argument, or a call out of order
        integer :: max_steps = 0        !! code of max_steps steps in one call of integrate
    end type integrator_id_t

    !> One integration by one of the project's integrators: the state, the counters and the
    !! checks of the arguments that every integrator has, and integrate and step, which
    !! drive an integrator's own steps.  The components belong to the integrators: only
    !! their procedures and those below write them; a driver reads an integration through
    !! stats() and dense().
    type, abstract, public :: integrator_t
        logical :: ready = .false.          !! init succeeded
        logical :: started = .false.        !! the direction and the first step size chosen
        integer :: n = 0                    !! size of the state
        real(dp) :: rtol = 0.0_dp           !! relative tolerance of the error test
        real(dp), allocatable :: atol(:)    !! (n) absolute tolerances of the error test
        real(dp) :: t = 0.0_dp              !! time reached: the end of the last step
        real(dp) :: dir = 1.0_dp            !! direction of the integration, +1 or -1
        real(dp) :: h = 0.0_dp              !! step size to try next (signed, units of t)
        real(dp) :: hu = 0.0_dp             !! the last step, [t - hu, t] (signed; 0 before)
        real(dp) :: h0_user = 0.0_dp        !! |h0| of init; 0: the integrator chooses it
        real(dp) :: hmax = huge(1.0_dp)     !! largest |h| (units of t)
        real(dp) :: tlast = 0.0_dp          !! time of integrate's last output
        real(dp) :: tcrit = 0.0_dp          !! time no step goes past (when have_tcrit)
        logical :: have_tcrit = .false.     !! tcrit is set
        integer :: max_steps = DEFAULT_MAX_STEPS    !! most steps in one call of integrate
        integer :: steps_call = 0           !! steps taken in this call of integrate or step
        integer :: nst = 0                  !! accepted steps since init
        integer :: nfe = 0                  !! calls of sys%rhs (difference Jacobians included)
        integer :: nje = 0                  !! Jacobian evaluations
        integer :: nlu = 0                  !! LU factorisations of the iteration matrix
        integer :: ncfn = 0                 !! step attempts rejected: corrector not converged
        integer :: netf = 0                 !! step attempts rejected by the local error test
        integer :: ns = 0                   !! forward sensitivities: their number (0: none)
        logical :: sens_errcon = .false.    !! they take part in the error test
        real(dp), allocatable :: satol(:, :)    !! (n, ns) their absolute tolerances
        integer :: nsp = 0                  !! points where their terms were taken (sens_point)
        integer :: nsit = 0                 !! iterations of their corrector
        integer :: nsdir = 0                !! their direct solves (a new matrix factored)
    contains
        ! what a driver calls
        procedure(init_i), deferred :: init
        procedure :: integrate => integrator_integrate
        procedure :: step => integrator_step
        procedure :: dense => integrator_dense
        procedure(stats_i), deferred :: stats
        procedure :: set_tcrit => integrator_set_tcrit
        procedure :: name => integrator_name
        procedure(sens_init_i), deferred :: sens_init
        procedure :: sens_dense => integrator_sens_dense
        procedure :: sens_dense_dot => default_sens_dense_dot
        procedure :: sens_dense_dots => default_sens_dense_dots
        ! what an integrator gives the procedures above
        procedure(identity_i), deferred :: identity
        procedure(start_i), deferred :: start
        procedure(one_step_i), deferred :: one_step
        procedure(solution_i), deferred :: solution
        procedure(at_tcrit_i), deferred :: at_tcrit
        procedure(dense_i), deferred :: dense_at
        procedure(sens_dense_i), deferred :: sens_dense_at
        ! what the integrators share
        procedure :: init_common
        procedure :: start_rhs
        procedure :: sens_init_common
        procedure :: check_in_step
        procedure :: refuse
        procedure :: prefix_time
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
        !> The solution (k = 0) or its derivative (k = 1) at t in the last step (dense_at:
        !! the integrator's, once dense has checked the integration and the size of dky).
        subroutine dense_i(s, t, k, dky, stat)
            import :: integrator_t, dp, status_t
            class(integrator_t), intent(in) :: s
            real(dp), intent(in) :: t
            integer, intent(in) :: k
            real(dp), intent(out) :: dky(:)
            type(status_t), intent(out) :: stat
        end subroutine dense_i
        !> The counters.
        pure function stats_i(s) result(st)
            import :: integrator_t, integrator_stats_t
            class(integrator_t), intent(in) :: s
            type(integrator_stats_t) :: st
        end function stats_i
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
        !> The sensitivities (k = 0) or their derivative (k = 1) at t in the last step
        !! (sens_dense_at: the integrator's, once sens_dense has checked that there are
        !! sensitivities and the shape of ds).
        subroutine sens_dense_i(s, t, k, ds, stat)
            import :: integrator_t, dp, status_t
            class(integrator_t), intent(in) :: s
            real(dp), intent(in) :: t
            integer, intent(in) :: k
            real(dp), intent(out) :: ds(:, :)           !! (n, ns)
            type(status_t), intent(out) :: stat
        end subroutine sens_dense_i
    end interface

    abstract interface
        !> The integrator's name and status codes.
        pure function identity_i(s) result(id)
            import :: integrator_t, integrator_id_t
            class(integrator_t), intent(in) :: s
            type(integrator_id_t) :: id
        end function identity_i
        !> The first step size, once the direction is known (integrate and step call it
        !! before the first step).
        subroutine start_i(s, sys, tout, have_tout, stat)
            import :: integrator_t, ode_system_t, dp, status_t
            class(integrator_t), intent(inout) :: s
            class(ode_system_t), intent(inout) :: sys
            real(dp), intent(in) :: tout        !! a time the caller wants to reach
            logical, intent(in) :: have_tout    !! tout is given (else it is t)
            type(status_t), intent(out) :: stat
        end subroutine start_i
        !> One accepted step of the method (never past tcrit), with its retries.
        subroutine one_step_i(s, sys, stat)
            import :: integrator_t, ode_system_t, status_t
            class(integrator_t), intent(inout) :: s
            class(ode_system_t), intent(inout) :: sys
            type(status_t), intent(out) :: stat
        end subroutine one_step_i
        !> The solution at t.
        pure subroutine solution_i(s, y)
            import :: integrator_t, dp
            class(integrator_t), intent(in) :: s
            real(dp), intent(out) :: y(:)       !! (n)
        end subroutine solution_i
        !> True when t stands at tcrit up to roundoff.
        pure logical function at_tcrit_i(s)
            import :: integrator_t
            class(integrator_t), intent(in) :: s
        end function at_tcrit_i
    end interface

    public :: too_much_accuracy, default_sens_point, common_stats, dense_zero

contains

    !> Steps up to tout and the solution there: the integrator's steps (one_step, never past
    !! tcrit) until one reaches tout, then its dense output at tout.  tout may lie anywhere
    !! ahead of the last output time in the direction of the integration, which the first
    !! call fixes (the first step size is chosen then: start).
    !!
    !! sys  [in,out] the right-hand side.
    !! tout [in]  output time.
    !! y    [out] (n) the solution at tout; on failure the solution at the time reached
    !!            (stats()%t_current), or 0 when y does not fit or there was no init.
    !! stat [out] STATUS_OK; the integrator's illegal-input code (no init, size(y) /= n,
    !!            tout behind the last output time, tcrit behind tout), its max-steps code
    !!            (max_steps steps in this call without reaching tout), or the failure of
    !!            one of its steps.
    subroutine integrator_integrate(s, sys, tout, y, stat)
        class(integrator_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: tout
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        type(integrator_id_t) :: id
        character(len=200) :: buf
        stat%code = STATUS_OK
        if (.not. s%ready .or. size(y) /= s%n) then
            y = 0.0_dp
            call s%refuse('integrate: not initialised, or size(y) /= n', stat)
            return
        end if
        call s%solution(y)
        if (.not. s%started) then
            if (tout == s%t) then
                s%tlast = tout
                return
            end if
            s%dir = sign(1.0_dp, tout - s%t)
        else if ((tout - s%tlast)*s%dir < 0.0_dp) then
            write (buf, '(a,es13.5e3,a,es13.5e3,a)') 'integrate: tout = ', tout, &
                ' is behind the last output time ', s%tlast, ' in the direction of integration'
            call s%refuse(trim(buf), stat)
            return
        end if
        if (s%have_tcrit) then
            if ((s%tcrit - tout)*s%dir < 0.0_dp) then
                write (buf, '(a,es13.5e3,a,es13.5e3)') 'integrate: tcrit = ', s%tcrit, &
                    ' is behind tout = ', tout
                call s%refuse(trim(buf), stat)
                return
            end if
        end if
        if (.not. s%started) then
            call s%start(sys, tout, .true., stat)
            if (stat%code /= STATUS_OK) return
        end if
        s%steps_call = 0
        do
            if ((s%t - tout)*s%dir >= 0.0_dp) then
                call s%dense_at(tout, 0, y, stat)
                if (stat%code /= STATUS_OK) then
                    call s%solution(y)
                    return
                end if
                s%tlast = tout
                return
            end if
            if (s%have_tcrit) then
                if (s%at_tcrit()) then
                    call s%solution(y)
                    s%tlast = tout
                    return
                end if
            end if
            if (s%steps_call >= s%max_steps) then
                id = s%identity()
                write (buf, '(a,i0,a,es15.7e3,a,es15.7e3)') ': ', s%max_steps, &
                    ' steps taken in this call without reaching tout = ', tout, &
                    '; t reached = ', s%t
                call set_error(stat, id%max_steps, trim(id%name)//trim(buf))
                call s%solution(y)
                return
            end if
            call s%one_step(sys, stat)
            if (stat%code /= STATUS_OK) then
                call s%solution(y)
                return
            end if
            s%steps_call = s%steps_call + 1
        end do
    end subroutine integrator_integrate

    !> Take exactly one step (never past tcrit).  After it, dense() gives the solution
    !! anywhere in [t_current - h_last, t_current].
    !!
    !! sys  [in,out] the right-hand side.
    !! stat [out] as for integrate; the illegal-input code also when the integration
    !!            already stands at tcrit.
    !! tout [in, optional] only used before the first step: a time the caller wants to
    !!            reach (fixes the direction and scales the first step size); without it
    !!            the direction is towards tcrit if set, else forward.
    subroutine integrator_step(s, sys, stat, tout)
        class(integrator_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: tout
        real(dp) :: th
        logical :: have
        stat%code = STATUS_OK
        if (.not. s%ready) then
            call s%refuse('step: not initialised', stat)
            return
        end if
        if (.not. s%started) then
            have = .false.
            th = s%t
            if (present(tout)) then
                if (tout /= s%t) then
                    have = .true.
                    th = tout
                end if
            end if
            if (.not. have .and. s%have_tcrit) then
                if (s%tcrit /= s%t) then
                    have = .true.
                    th = s%tcrit
                end if
            end if
            if (have) s%dir = sign(1.0_dp, th - s%t)
            if (s%have_tcrit) then
                if ((s%tcrit - s%t)*s%dir <= 0.0_dp) then
                    call s%refuse('step: the integration already stands at tcrit', stat)
                    return
                end if
            end if
            call s%start(sys, th, have, stat)
            if (stat%code /= STATUS_OK) return
        else if (s%have_tcrit) then
            if (s%at_tcrit()) then
                call s%refuse('step: the integration already stands at tcrit', stat)
                return
            end if
        end if
        s%steps_call = 0
        call s%one_step(sys, stat)
        if (stat%code == STATUS_OK) s%steps_call = 1
    end subroutine integrator_step

    !> Set (tcrit present) or remove (absent) the hard stop time.
    !!
    !! tcrit [in, optional] new stop time; it must not lie behind the time already reached
    !!       (then stat = the illegal-input code and the old setting stays).
    !! stat  [out, optional] STATUS_OK or the integrator's illegal-input code.
    subroutine integrator_set_tcrit(s, tcrit, stat)
        class(integrator_t), intent(inout) :: s
        real(dp), intent(in), optional :: tcrit
        type(status_t), intent(out), optional :: stat
        character(len=120) :: buf
        if (present(stat)) stat%code = STATUS_OK
        if (.not. present(tcrit)) then
            s%have_tcrit = .false.
            return
        end if
        if (s%started .and. (tcrit - s%t)*s%dir < 0.0_dp) then
            if (present(stat)) then
                write (buf, '(a,es13.5e3,a,es13.5e3)') 'set_tcrit: tcrit = ', tcrit, &
                    ' is behind the time reached ', s%t
                call s%refuse(trim(buf), stat)
            end if
            return
        end if
        s%tcrit = tcrit
        s%have_tcrit = .true.
    end subroutine integrator_set_tcrit

    !> The solution (k = 0) or its k-th derivative at t within the last step: the
    !! integrator's dense output (dense_at) once the integration and dky are checked.
    !!
    !! t    [in]  time in [t_current - h_last, t_current] (roundoff tolerated).
    !! k    [in]  derivative order: 0 or 1 for every integrator (LSODA: up to its order).
    !! dky  [out] (n) d^k y/dt^k at t (units of y per unit of t^k).
    !! stat [out] STATUS_OK or the integrator's illegal-input code (no init, size(dky) /= n,
    !!            t outside the step, a bad k).
    subroutine integrator_dense(s, t, k, dky, stat)
        class(integrator_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(:)
        type(status_t), intent(out) :: stat
        if (.not. s%ready .or. size(dky) /= s%n) then
            dky = 0.0_dp
            stat%code = STATUS_OK
            call s%refuse('dense: not initialised, or size(dky) /= n', stat)
            return
        end if
        call s%dense_at(t, k, dky, stat)
    end subroutine integrator_dense

    !> The zero th of dir*y(iy) in [ta, tb] within the last step (fa = dir*y(iy) at ta > 0
    !! >= fb at tb): Illinois' regula falsi on the dense output, to roundoff in t.
    subroutine dense_zero(s, iy, dir, ta, tb, fa, fb, th, stat)
        class(integrator_t), intent(in) :: s
        integer, intent(in) :: iy
        real(dp), intent(in) :: dir
        real(dp), intent(inout) :: ta, tb, fa, fb
        real(dp), intent(out) :: th
        type(status_t), intent(out) :: stat
        real(dp) :: y(s%n), tc, fc
        integer :: k
        th = 0.5_dp*(ta + tb)
        stat%code = STATUS_OK
        do k = 1, 100
            tc = tb - fb*(tb - ta)/(fb - fa)
            if (.not. (tc > min(ta, tb) .and. tc < max(ta, tb))) tc = 0.5_dp*(ta + tb)
            call s%dense(tc, 0, y, stat)
            if (stat%code /= STATUS_OK) return
            fc = dir*y(iy)
            if (fc == 0.0_dp) then
                ta = tc
                tb = tc
                exit
            end if
            if (fc > 0.0_dp) then
                ta = tc
                fa = fc
                fb = 0.5_dp*fb
            else
                tb = tc
                fb = fc
                fa = 0.5_dp*fa
            end if
            if (abs(tb - ta) <= 4.0_dp*epsilon(1.0_dp)*abs(tb)) exit
        end do
        th = 0.5_dp*(ta + tb)
    end subroutine dense_zero

    !> The sensitivities (k = 0) or their k-th derivative at t within the last step: the
    !! integrator's (sens_dense_at) once there are sensitivities and ds fits them.
    !!
    !! ds   [out] (n, ns).
    !! stat [out] STATUS_OK or the integrator's illegal-input code (no sensitivities, ds not
    !!            n x ns, t outside the step, a bad k).
    subroutine integrator_sens_dense(s, t, k, ds, stat)
        class(integrator_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: ds(:, :)
        type(status_t), intent(out) :: stat
        if (.not. s%ready .or. s%ns == 0 .or. size(ds, 1) /= s%n .or. size(ds, 2) /= s%ns) then
            ds = 0.0_dp
            stat%code = STATUS_OK
            call s%refuse('sens_dense: no sensitivities, or ds is not n x ns', stat)
            return
        end if
        call s%sens_dense_at(t, k, ds, stat)
    end subroutine integrator_sens_dense

    !> The integrator's name as written in output files: 'lsoda' or 'radau'.
    pure function integrator_name(s) result(nm)
        class(integrator_t), intent(in) :: s
        character(len=:), allocatable :: nm
        type(integrator_id_t) :: id
        id = s%identity()
        nm = trim(id%name)
    end function integrator_name

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

    !> v(k, o) = g(:, o) . s_k(t) for several vectors at once (default: sens_dense_dot on
    !! each column; an integrator may share its interpolation between them).
    !!
    !! g    [in]  (n, m) the vectors.
    !! v    [out] (ns, m) the projections.
    !! stat [out] as sens_dense.
    subroutine default_sens_dense_dots(s, t, g, v, stat)
        class(integrator_t), intent(in) :: s
        real(dp), intent(in) :: t
        real(dp), intent(in) :: g(:, :)
        real(dp), intent(out) :: v(:, :)
        type(status_t), intent(out) :: stat
        integer :: o
        v = 0.0_dp
        stat%code = STATUS_OK
        do o = 1, size(g, 2)
            call s%sens_dense_dot(t, g(:, o), v(:, o), stat)
            if (stat%code /= STATUS_OK) return
        end do
    end subroutine default_sens_dense_dots

    !> What every integrator's init does besides its method: the checks of the arguments
    !! they all take (n >= 1; atol of size 1 or n, each >= 0 and finite; hmax > 0;
    !! max_steps >= 1), then the options, atol (of n) and the state and counters at t0.
    !! Not ready: the integrator's init checks rtol (its range is the integrator's own),
    !! sets up its method and makes the integration ready.
    !!
    !! n    [in]  size of the state, size(y0).
    !! stat [out] STATUS_OK, or the integrator's illegal-input code with what is wrong.
    !! t0, atol, tcrit, h0, hmax, max_steps [in] as given to init.
    subroutine init_common(s, t0, n, atol, stat, tcrit, h0, hmax, max_steps)
        class(integrator_t), intent(inout) :: s
        real(dp), intent(in) :: t0
        integer, intent(in) :: n
        real(dp), intent(in) :: atol(:)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: tcrit, h0, hmax
        integer, intent(in), optional :: max_steps
        character(len=120) :: buf
        stat%code = STATUS_OK
        s%ready = .false.
        s%started = .false.
        if (n < 1) then
            call s%refuse('init: empty state vector', stat)
            return
        end if
        if (size(atol) /= 1 .and. size(atol) /= n) then
            write (buf, '(a,i0,a,i0)') 'init: size(atol) = ', size(atol), ' must be 1 or n = ', n
            call s%refuse(trim(buf), stat)
            return
        end if
        if (.not. all(atol >= 0.0_dp .and. atol < huge(1.0_dp))) then
            call s%refuse('init: atol has a negative or non-finite entry', stat)
            return
        end if
        s%hmax = huge(1.0_dp)
        if (present(hmax)) then
            if (.not. (hmax > 0.0_dp)) then
                call s%refuse('init: hmax must be > 0', stat)
                return
            end if
            s%hmax = hmax
        end if
        s%max_steps = DEFAULT_MAX_STEPS
        if (present(max_steps)) then
            if (max_steps < 1) then
                call s%refuse('init: max_steps must be >= 1', stat)
                return
            end if
            s%max_steps = max_steps
        end if
        s%h0_user = 0.0_dp
        if (present(h0)) s%h0_user = abs(h0)
        s%have_tcrit = present(tcrit)
        if (present(tcrit)) s%tcrit = tcrit
        s%n = n
        if (allocated(s%atol)) then
            if (size(s%atol) /= n) deallocate (s%atol)
        end if
        if (.not. allocated(s%atol)) allocate (s%atol(n))
        if (size(atol) == 1) then
            s%atol = atol(1)
        else
            s%atol = atol
        end if
        s%t = t0
        s%tlast = t0
        s%dir = 1.0_dp
        s%h = 0.0_dp
        s%hu = 0.0_dp
        s%steps_call = 0
        s%nst = 0
        s%nfe = 0
        s%nje = 0
        s%nlu = 0
        s%ncfn = 0
        s%netf = 0
        s%ns = 0
        s%nsp = 0
        s%nsit = 0
        s%nsdir = 0
    end subroutine init_common

    !> f(t0, y0) for init: the first evaluation of the right-hand side (nfe = 1); a failure's
    !! message prefixed with the integrator's name and t0.
    subroutine start_rhs(s, sys, y0, f0, stat)
        class(integrator_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: y0(:)               !! (n) the state at t0
        real(dp), intent(out) :: f0(:)              !! (n) f(t0, y0)
        type(status_t), intent(out) :: stat
        call sys%rhs(s%t, y0, f0, stat)
        s%nfe = 1
        if (stat%code /= STATUS_OK) call s%prefix_time(stat, s%t)
    end subroutine start_rhs

    !> What every integrator's sens_init does besides its method: the checks (after init
    !! and before the first step; s0 of n rows and ns >= 1 columns; scale, when given, of
    !! ns entries each > 0), error_control, and the sensitivities' absolute tolerances
    !! satol(i, k) = atol_i scale_k, with floor for an atol_i that is 0 (the weight would be
    !! infinite where s = 0).  ns = size(s0, 2) on success, 0 on failure.
    !!
    !! s0    [in]  (n, ns) as given to sens_init.
    !! floor [in]  the tolerance that stands for atol_i = 0 (units of y).
    !! stat  [out] STATUS_OK, or the integrator's illegal-input code with what is wrong.
    !! scale, error_control [in, optional] as given to sens_init.
    subroutine sens_init_common(s, s0, floor, stat, scale, error_control)
        class(integrator_t), intent(inout) :: s
        real(dp), intent(in) :: s0(:, :)
        real(dp), intent(in) :: floor
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: scale(:)
        logical, intent(in), optional :: error_control
        real(dp) :: sc(size(s0, 2)), w
        integer :: ns, n, k, i
        stat%code = STATUS_OK
        s%ns = 0
        n = s%n
        ns = size(s0, 2)
        sc = 1.0_dp
        if (.not. s%ready .or. s%started) then
            call s%refuse('sens_init: after init and before the first step only', stat)
            return
        else if (size(s0, 1) /= n .or. ns < 1) then
            call s%refuse('sens_init: s0 must be n x ns, ns >= 1', stat)
            return
        else if (present(scale)) then
            if (size(scale) /= ns .or. .not. all(scale > 0.0_dp)) then
                call s%refuse('sens_init: scale must have ns entries, each > 0', stat)
                return
            end if
            sc = scale
        end if
        s%sens_errcon = .false.
        if (present(error_control)) s%sens_errcon = error_control
        if (allocated(s%satol)) then
            if (size(s%satol, 1) /= n .or. size(s%satol, 2) /= ns) deallocate (s%satol)
        end if
        if (.not. allocated(s%satol)) allocate (s%satol(n, ns))
        do k = 1, ns
            do i = 1, n
                w = s%atol(i)
                if (.not. (w > 0.0_dp)) w = floor
                s%satol(i, k) = w*sc(k)
            end do
        end do
        s%ns = ns
    end subroutine sens_init_common

    !> The illegal-input code, '<name> <what>: t = ... is outside the last step [...]', when
    !! t is not within the last step [t - hu, t] up to roundoff, else STATUS_OK.
    subroutine check_in_step(s, t, what, stat)
        class(integrator_t), intent(in) :: s
        real(dp), intent(in) :: t                   !! the time asked for
        character(len=*), intent(in) :: what        !! the procedure asked, e.g. 'dense'
        type(status_t), intent(out) :: stat
        real(dp) :: tp, tol
        character(len=200) :: buf
        stat%code = STATUS_OK
        tol = 100.0_dp*epsilon(1.0_dp)*(abs(s%t) + abs(s%hu))
        tp = s%t - s%hu
        if (min(tp, s%t) - tol > t .or. t > max(tp, s%t) + tol) then
            write (buf, '(a,es15.7e3,a,es15.7e3,a,es15.7e3,a)') ': t = ', t, &
                ' is outside the last step [', min(tp, s%t), ', ', max(tp, s%t), ']'
            call s%refuse(what//trim(buf), stat)
        end if
    end subroutine check_in_step

    !> The counters and step sizes every integrator keeps, in integrator_stats_t (the
    !! integrator's stats adds its own; a plain procedure, so that it calls it directly).
    pure function common_stats(s) result(st)
        class(integrator_t), intent(in) :: s
        type(integrator_stats_t) :: st
        st%steps = s%nst
        st%rhs_evals = s%nfe
        st%jac_evals = s%nje
        st%lu_decomps = s%nlu
        st%conv_failures = s%ncfn
        st%error_test_failures = s%netf
        st%h_last = s%hu
        st%h_next = s%h
        st%t_current = s%t
        st%sens_points = s%nsp
        st%sens_iterations = s%nsit
        st%sens_direct = s%nsdir
    end function common_stats

    !> stat = the integrator's illegal-input code with the message '<name> <what>'.
    subroutine refuse(s, what, stat)
        class(integrator_t), intent(in) :: s
        character(len=*), intent(in) :: what        !! the call and what is wrong with it
        type(status_t), intent(inout) :: stat
        type(integrator_id_t) :: id
        id = s%identity()
        call set_error(stat, id%illegal_input, trim(id%name)//' '//what)
    end subroutine refuse

    !> A failure's message prefixed with the integrator's name and the time reached,
    !! '<name> at t = ...: <message>'.
    subroutine prefix_time(s, stat, t)
        class(integrator_t), intent(in) :: s
        type(status_t), intent(inout) :: stat
        real(dp), intent(in) :: t                   !! the time reached
        character(len=40) :: buf
        write (buf, '(a,es15.7e3,a)') ' at t = ', t, ':'
        if (allocated(stat%msg)) then
            stat%msg = s%name()//trim(buf)//' '//stat%msg
        else
            stat%msg = s%name()//trim(buf)//' (no message)'
        end if
    end subroutine prefix_time

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
