!> LSODA-style integrator for y' = f(t, y): variable step, variable order Nordsieck-array
!! methods with automatic switching between non-stiff and stiff integration.
!!
!! Algorithm (written from the published descriptions: Hindmarsh, "ODEPACK, a systematized
!! collection of ODE solvers" and the LSODE/LSODA documentation; Petzold 1983, "Automatic
!! selection of methods for solving stiff and nonstiff systems of ODEs"; Byrne & Hindmarsh 1975
!! on Nordsieck-array methods):
!!
!! * Non-stiff: Adams-Moulton, orders 1-12, corrector solved by functional (fixed-point)
!!   iteration.  While it runs, the iteration gives an estimate of the local Lipschitz
!!   constant of f; the step is also limited to the (approximate) stability region.
!! * Stiff: BDF, orders 1-5, corrector solved by a chord Newton iteration with the
!!   iteration matrix P = I - h*l0*J, factored by LAPACK (module lapack_wrap).  J is the
!!   analytic Jacobian when the system has one, else a finite-difference Jacobian; a system
!!   with a structured Jacobian may factor and solve with P itself (ode_system's
!!   has_iteration_solver).  P is kept while it serves and rebuilt after a convergence
!!   failure, every 20 steps, or when h*l0 changed by more than 30 %.
!! * Switching: at least 20 steps after the last switch, on every step the step size the
!!   other method could take (at the same accuracy, and for Adams inside its stability
!!   region) is compared with the current one; Adams -> BDF when BDF would be at least
!!   5 times larger, BDF -> Adams when Adams would not be smaller.
!! * Error control: local error estimate per step in the weighted max-norm (as LSODA:
!!   ||v|| = max_i |v_i|/w_i, w_i = rtol*|y_i| + atol_i), order and step chosen to keep it
!!   below 1.
!! * Output: the solution at any t inside the last step by interpolation from the Nordsieck
!!   array (integrate, dense), optional hard stop time tcrit never stepped over.
!! * Forward sensitivities (sens_init, sens_dense), by the staggered direct method (Caracotsios
!!   & Stewart 1985; Maly & Petzold 1996): the sensitivities s_k = dy/dp_k have a Nordsieck
!!   array of their own, predicted, rescaled and corrected with the state's.  Once the
!!   state's corrector has converged (and, by default, passed the error test), the step's
!!   formula is solved for the sensitivities at the new point (t_n, y_n):
!!       (I - h l0 J) a = h (J z_pred + df/dp) - z'_pred h,   s_n = z_pred + l0 a,
!!   with the exact products J v and df/dp of the system (ode_system's sens_point, sens_jv).
!!   A BDF step solves it with its own Newton matrix (the chord iteration, residuals with the
!!   exact J); an Adams step by a chord iteration with the inverse of the sensitivities' own
!!   I - h l0 J (every column in one product).  An iteration that does not contract fast
!!   enough ends in a direct solve with I - h l0 J formed and inverted anew.  The
!!   sensitivities do not change the state's steps unless they are asked into the error test
!!   (error_control): then the step's error norm and the order selection include theirs.
!!
!! The code: a step (take_step) is its named parts: begin_step (the step's start after the
!! first step, a switch of method or a change of h by the driver), predict, correct (the
!! corrector), error_estimate (the local error test), accept or a retry
!! (retry_after_convergence_failure, retry_after_error_test), consider_switch (the switch
!! of method) and choose_next with choose_order (the order and h of the next step).
!! integrate and step are integrator_t's (module ode_system): this module gives them the
!! first step size (lsoda_start) and one accepted step with its checks (lsoda_one_step).
!!
!! All state lives in a `lsoda_t` object (with what every integrator keeps, its
!! integrator_t part), so independent integrations can be interleaved.
!! No routine stops the program: every failure is returned in a status_t with one of the
!! LSODA_ERR_* codes (or the code the right-hand side returned) and a message naming the
!! cause and the time reached; the solution up to the failure is kept.
module lsoda
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, LSODA_ERR_MAX_STEPS, &
        LSODA_ERR_TOO_MUCH_ACCURACY, LSODA_ERR_ERROR_TEST, LSODA_ERR_CONVERGENCE, &
        LSODA_ERR_ILLEGAL_INPUT, LSODA_ERR_SINGULAR
    use ode_system, only: ode_system_t, integrator_t, integrator_stats_t, integrator_id_t, &
        common_stats, METHOD_ADAMS, METHOD_BDF
    use lapack_wrap, only: la_lu_factor, la_lu_solve, la_small_lu_solve, la_small_inverse
    use unused_arg, only: unused
    implicit none
    private

    public :: METHOD_ADAMS, METHOD_BDF

    integer, parameter :: MAXORD_ADAMS = 12
    integer, parameter :: MAXORD_BDF = 5
    integer, parameter :: LMAX_ALL = MAXORD_ADAMS + 1
    real(dp), parameter :: UROUND = epsilon(1.0_dp)
    !> Approximate stability-region sizes |h*L| of the Adams methods of order 1..12
    !! (the values Petzold's LSODA uses).
    real(dp), parameter :: SM1(MAXORD_ADAMS) = [0.5_dp, 0.575_dp, 0.55_dp, 0.45_dp, 0.35_dp, &
        0.25_dp, 0.2_dp, 0.15_dp, 0.1_dp, 0.075_dp, 0.05_dp, 0.025_dp]
    real(dp), parameter :: CCMAX = 0.3_dp          !! rebuild P when h*l0 changed by more
    integer, parameter :: MSBP = 20                !! rebuild P at least every MSBP steps
    integer, parameter :: MAXCOR = 3               !! corrector iterations per attempt
    integer, parameter :: MXNCF = 10               !! convergence failures per step
    integer, parameter :: MXNEF = 10               !! error-test failures per step
    integer, parameter :: SWITCH_WAIT = 20         !! steps after a switch before the next test
    real(dp), parameter :: SWITCH_RATIO = 5.0_dp   !! cost ratio of a BDF to an Adams step
    real(dp), parameter :: HMIN = 0.0_dp           !! smallest |h| (LSODA's HMIN; none here)
    integer, parameter :: SENS_MAXIT = 4           !! sensitivity corrector iterations
    real(dp), parameter :: SENS_CONV = 0.5_dp      !! their test: this part of the state's
    real(dp), parameter :: SENS_CONV_EC = 0.1_dp   !! the same in the error control (Adams)

    ! outcome of one call of take_step (kflag); below KF_OK while retrying, the number of
    ! error-test failures of the step so far, negated
    integer, parameter :: KF_OK = 0, KF_ERRTEST = -1, KF_CONV = -2, KF_SINGULAR = -3, &
        KF_FATAL = -4
    ! what the jstart of a step says (LSODA's JSTART)
    integer, parameter :: JS_FIRST = 0            !! the first step: order 1, new coefficients
    integer, parameter :: JS_GOING = 1            !! a step after an accepted one
    integer, parameter :: JS_SWITCHED = -1        !! the method switched on the last step
    integer, parameter :: JS_NEW_H = -2           !! h changed by the driver (tcrit)
    ! outcome of the corrector (correct)
    integer, parameter :: CORR_CONVERGED = 0      !! the iteration converged
    integer, parameter :: CORR_DIVERGED = 1       !! it did not, in MAXCOR iterations
    integer, parameter :: CORR_SINGULAR = 2       !! P is singular
    integer, parameter :: CORR_UNSOLVED = 3       !! the solve with P failed
    integer, parameter :: CORR_FATAL = 4          !! f or J failed (the step is undone)

    !> One integration by LSODA: its options, the Nordsieck arrays of the state and of the
    !! sensitivities, the methods' coefficients, the step's and the method's state, the
    !! iteration matrices and the work vectors (what every integrator keeps, as t, h, the
    !! tolerances and the counters, is integrator_t's).  Where ODEPACK's LSODA has a name
    !! for a quantity, it is kept.
    type, extends(integrator_t), public :: lsoda_t
        private
        ! the options of the next init (set_options)
        integer :: opt_order_adams = MAXORD_ADAMS   !! highest Adams order asked for
        integer :: opt_order_bdf = MAXORD_BDF       !! highest BDF order asked for
        logical :: opt_start_bdf = .false.          !! the first step by BDF
        logical :: opt_adams_only = .false.         !! Adams throughout, never BDF
        ! the Nordsieck array and the vectors of a step
        real(dp), allocatable :: yh(:, :)   !! (n, 13) Nordsieck array: column j+1 h^j y^(j)/j! at t
        real(dp), allocatable :: rewt(:)    !! (n) reciprocal error weights 1/(rtol |y| + atol)
        real(dp), allocatable :: y(:)       !! (n) the corrector's iterate at t (units of y)
        real(dp), allocatable :: savf(:)    !! (n) f at y (units of y per unit of t); scratch
        real(dp), allocatable :: acor(:)    !! (n) the step's correction, then error estimate
        real(dp), allocatable :: ftem(:)    !! (n) f at a perturbed y (difference Jacobian)
        real(dp), allocatable :: wm(:, :)   !! (n, n) or (1, 1): P = I - h l0 J, then LU factors
        integer, allocatable :: ipiv(:)     !! (n) the pivots of wm's factors
        ! the coefficients of the methods (set_coefficients) and of the current one
        real(dp) :: elco(LMAX_ALL, MAXORD_ADAMS, 2) = 0.0_dp  !! l_j (j, order, method)
        real(dp) :: tesco(3, MAXORD_ADAMS, 2) = 0.0_dp    !! error divisors, orders q-1, q, q+1
        real(dp) :: cm1(MAXORD_ADAMS) = 0.0_dp  !! Adams l_(q+1) tesco(2, q) (switching test)
        real(dp) :: cm2(MAXORD_BDF) = 0.0_dp    !! BDF l_(q+1) tesco(2, q) (switching test)
        real(dp) :: el(LMAX_ALL) = 0.0_dp       !! l_j of the current method and order
        ! the step
        real(dp) :: told = 0.0_dp       !! t at the start of the step (restored on a retry)
        real(dp) :: hold = 0.0_dp       !! the h yh is scaled to (units of t)
        real(dp) :: hmxi = 0.0_dp       !! 1/hmax, 0 without hmax (per unit of t)
        real(dp) :: rc = 0.0_dp         !! h l0 over the h l0 of P (P rebuilt beyond 1 +- CCMAX)
        real(dp) :: el0 = 1.0_dp        !! l0 when rc was last brought up to date
        real(dp) :: crate = 0.7_dp      !! the corrector's estimated rate of convergence
        real(dp) :: conit = 0.0_dp      !! 0.5/(nq + 2): the corrector's test, per tesco(2)
        real(dp) :: rmax = 1.0e4_dp     !! largest factor of the next change of h
        ! the methods and their switching
        real(dp) :: pdest = 0.0_dp      !! Lipschitz estimate of f from the Adams corrector (1/t)
        real(dp) :: pdlast = 0.0_dp     !! the last nonzero pdest
        real(dp) :: pdnorm = 0.0_dp     !! weighted norm of J at the last P (per unit of t)
        integer :: nq = 1               !! order of the current step
        integer :: l = 2                !! nq + 1: the columns of yh in use
        integer :: lmax = 13            !! highest order of the current method + 1
        integer :: meth = METHOD_ADAMS  !! method of the current step (METHOD_ADAMS, _BDF)
        integer :: mused = 0            !! method of the last accepted step (0 before it)
        integer :: nqu = 0              !! order of the last accepted step (0 before it)
        integer :: meth0 = METHOD_ADAMS !! method of the first step
        integer :: mxordn = MAXORD_ADAMS    !! highest Adams order of this integration
        integer :: mxords = MAXORD_BDF      !! highest BDF order of this integration
        logical :: adams_only = .false. !! never switch to BDF
        logical :: structured = .false. !! the system solves with P (has_iteration_solver)
        integer :: ialth = 2            !! steps until a change of order and h is considered
        integer :: icount = SWITCH_WAIT !! steps until the next test of a switch of method
        integer :: irflag = 0           !! 1: the last change of h was held by Adams' stability
        integer :: nslp = 0             !! nst when P was last formed
        integer :: jstart = JS_FIRST    !! what the next step is (JS_*)
        integer :: kflag = KF_OK        !! outcome of the last take_step (KF_*)
        logical :: ipup = .false.       !! P is to be formed anew before the corrector
        logical :: jcur = .false.       !! J was formed at this step's predicted point
        integer :: nswitch = 0          !! switches of method since init
        ! forward sensitivities (sens_init): ns columns of n, one vector of n ns
        integer :: nsn = 0                     !! n ns
        real(dp), allocatable :: zh(:, :)      !! (nsn, LMAX_ALL) their Nordsieck array
        real(dp), allocatable :: srewt(:)      !! (nsn) their reciprocal error weights
        real(dp), allocatable :: sacor(:)      !! (nsn) their correction (as acor)
        real(dp), allocatable :: sdfdp(:, :)   !! (n, ns) df/dp at the step's point
        real(dp), allocatable :: sb(:)         !! (nsn) sens_correct's right-hand side
        real(dp), allocatable :: sd(:)         !! (nsn) sens_correct's change of the iterate
        real(dp), allocatable :: sjv(:)        !! (nsn) products J v
        real(dp), allocatable :: sjm(:, :)     !! (n, n) their own matrix I - h l0 J
        real(dp), allocatable :: sinv(:, :)    !! (n, n) its inverse (all columns at once)
        real(dp) :: shl0 = 0.0_dp              !! the h l0 of sjm (units of t)
        integer :: snslp = 0                   !! nst when sjm was formed
        logical :: shave = .false.             !! sjm is formed
        real(dp) :: scrate = 0.7_dp            !! their iteration's rate of convergence
    contains
        procedure :: init => lsoda_init
        procedure :: dense_at => lsoda_dense_at
        procedure :: stats => lsoda_get_stats
        procedure :: set_options => lsoda_set_options
        procedure :: sens_init => lsoda_sens_init
        procedure :: sens_dense_at => lsoda_sens_dense_at
        procedure :: sens_dense_dot => lsoda_sens_dense_dot
        procedure :: sens_dense_dots => lsoda_sens_dense_dots
        procedure :: start => lsoda_start
        procedure :: one_step => lsoda_one_step
        procedure :: solution => lsoda_solution
        procedure :: at_tcrit => lsoda_at_tcrit
        procedure :: identity => lsoda_identity
    end type lsoda_t

contains

    ! ------------------------------------------------------------------------------------
    ! Public routines (integrate, step and set_tcrit are integrator_t's)
    ! ------------------------------------------------------------------------------------

    !> Start an integration at (t0, y0).
    !!
    !! sys       [in,out] the right-hand side; called once here for f(t0, y0).
    !! t0        [in]  initial time (units of the problem's independent variable).
    !! y0        [in]  initial state, size n >= 1.
    !! rtol      [in]  relative tolerance, >= 0.
    !! atol      [in]  absolute tolerance, size 1 (same for all components) or n, each >= 0
    !!                 and finite.  Error weights w_i = rtol*|y_i| + atol_i must stay > 0.
    !! stat      [out] STATUS_OK; LSODA_ERR_ILLEGAL_INPUT for bad arguments; or the code
    !!                 the right-hand side returned.
    !! tcrit     [in, optional] time the integration must never step past.
    !! h0        [in, optional] first step size to try (sign ignored); default: chosen
    !!                 from f(t0,y0), the tolerances and the first output time.
    !! hmax      [in, optional] largest |h| (> 0); default unlimited.
    !! max_steps [in, optional] most steps in one call of integrate (default 500000).
    !! The options of set_options (highest orders, start_bdf, nonstiff_only) apply.
    subroutine lsoda_init(s, sys, t0, y0, rtol, atol, stat, tcrit, h0, hmax, max_steps)
        class(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t0
        real(dp), intent(in) :: y0(:)
        real(dp), intent(in) :: rtol
        real(dp), intent(in) :: atol(:)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: tcrit
        real(dp), intent(in), optional :: h0
        real(dp), intent(in), optional :: hmax
        integer, intent(in), optional :: max_steps
        integer :: n, nwm
        character(len=120) :: buf

        n = size(y0)
        call s%init_common(t0, n, atol, stat, tcrit, h0, hmax, max_steps)
        if (stat%code /= STATUS_OK) return
        if (.not. (rtol >= 0.0_dp)) then
            write (buf, '(a,es11.3e3,a)') 'lsoda init: rtol = ', rtol, ' is negative'
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        s%mxordn = s%opt_order_adams
        s%mxords = s%opt_order_bdf
        if (s%mxordn < 1 .or. s%mxordn > MAXORD_ADAMS .or. s%mxords < 1 &
            .or. s%mxords > MAXORD_BDF) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda init: max_order_adams must '// &
                'be in 1..12 and max_order_bdf in 1..5')
            return
        end if
        s%meth0 = merge(METHOD_BDF, METHOD_ADAMS, s%opt_start_bdf)
        s%adams_only = s%opt_adams_only
        if (s%adams_only .and. s%meth0 == METHOD_BDF) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda init: start_bdf and '// &
                'nonstiff_only exclude each other')
            return
        end if
        s%rtol = rtol
        s%hmxi = 0.0_dp
        if (present(hmax)) s%hmxi = 1.0_dp/hmax

        if (allocated(s%yh)) then
            if (size(s%yh, 1) /= n) deallocate (s%yh)
        end if
        if (.not. allocated(s%yh)) allocate (s%yh(n, LMAX_ALL))
        ! a system that solves with P itself needs no n x n matrix here
        s%structured = sys%has_iteration_solver()
        nwm = n
        if (s%structured) nwm = 1
        if (allocated(s%wm)) then
            if (size(s%wm, 1) /= nwm) deallocate (s%wm)
        end if
        if (.not. allocated(s%wm)) allocate (s%wm(nwm, nwm))
        call realloc_vec(s%rewt, n)
        call realloc_vec(s%y, n)
        call realloc_vec(s%savf, n)
        call realloc_vec(s%acor, n)
        call realloc_vec(s%ftem, n)
        if (allocated(s%ipiv)) then
            if (size(s%ipiv) /= n) deallocate (s%ipiv)
        end if
        if (.not. allocated(s%ipiv)) allocate (s%ipiv(n))
        s%yh = 0.0_dp
        s%wm = 0.0_dp
        s%acor = 0.0_dp
        s%ipiv = 0

        call set_coefficients(s%elco, s%tesco, s%cm1, s%cm2)

        s%told = t0
        s%hold = 0.0_dp
        s%nq = 1
        s%l = 2
        s%meth = s%meth0
        s%mused = 0
        s%nqu = 0
        s%jstart = JS_FIRST
        s%kflag = KF_OK
        s%nswitch = 0
        s%pdnorm = 0.0_dp
        s%nsn = 0

        s%yh(:, 1) = y0
        s%y = y0
        call s%start_rhs(sys, s%y, s%savf, stat)
        if (stat%code /= STATUS_OK) return
        s%yh(:, 2) = s%savf     ! f(t0,y0); scaled by h0 when the first step size is known
        s%ready = .true.
    end subroutine lsoda_init

    !> k-th derivative of the interpolating polynomial at t, within the last step (dense of
    !! integrator_t checks the integration and dky first).
    !!
    !! t    [in]  time in [t_current - h_last, t_current] (roundoff tolerated).
    !! k    [in]  derivative order, 0 <= k <= current order (order_next).
    !! dky  [out] size n: d^k y / dt^k at t (units of y per time**k).
    !! stat [out] STATUS_OK or LSODA_ERR_ILLEGAL_INPUT (t outside the step, bad k).
    subroutine lsoda_dense_at(s, t, k, dky, stat)
        class(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(:)
        type(status_t), intent(out) :: stat
        call interpolate(s, s%yh, s%n, t, k, dky, stat)
    end subroutine lsoda_dense_at

    !> Counters and method state (see integrator_stats_t).
    pure function lsoda_get_stats(s) result(st)
        class(lsoda_t), intent(in) :: s
        type(integrator_stats_t) :: st
        st = common_stats(s)
        st%method_switches = s%nswitch
        st%method_last = s%mused
        st%order_last = s%nqu
        st%method_next = s%meth
        st%order_next = s%nq
    end function lsoda_get_stats

    !> LSODA's own options, for the next init and those after it until set again (an
    !! option left out here returns to its default).
    !!
    !! max_order_adams [in, optional] highest Adams order, 1..12 (default 12).
    !! max_order_bdf   [in, optional] highest BDF order, 1..5 (default 5).
    !! start_bdf [in, optional] .true.: take the first step with BDF (as after a restart of
    !!                 a problem known to be stiff); default .false., Adams, as LSODA does.
    !!                 The automatic switching between the methods works as usual after it.
    !! nonstiff_only [in, optional] .true.: Adams throughout, never switch to BDF (the
    !!                 non-stiff method alone, for comparisons); not with start_bdf.
    !! init refuses values out of range (LSODA_ERR_ILLEGAL_INPUT).
    pure subroutine lsoda_set_options(s, max_order_adams, max_order_bdf, start_bdf, &
                                      nonstiff_only)
        class(lsoda_t), intent(inout) :: s
        integer, intent(in), optional :: max_order_adams, max_order_bdf
        logical, intent(in), optional :: start_bdf, nonstiff_only
        s%opt_order_adams = MAXORD_ADAMS
        s%opt_order_bdf = MAXORD_BDF
        s%opt_start_bdf = .false.
        s%opt_adams_only = .false.
        if (present(max_order_adams)) s%opt_order_adams = max_order_adams
        if (present(max_order_bdf)) s%opt_order_bdf = max_order_bdf
        if (present(start_bdf)) s%opt_start_bdf = start_bdf
        if (present(nonstiff_only)) s%opt_adams_only = nonstiff_only
    end subroutine lsoda_set_options

    !> LSODA's name and status codes for the procedures of integrator_t.
    pure function lsoda_identity(s) result(id)
        class(lsoda_t), intent(in) :: s
        type(integrator_id_t) :: id
        call unused(s)
        id = integrator_id_t('lsoda', LSODA_ERR_ILLEGAL_INPUT, LSODA_ERR_MAX_STEPS)
    end function lsoda_identity

    !> The solution at t: the Nordsieck array's first column.
    pure subroutine lsoda_solution(s, y)
        class(lsoda_t), intent(in) :: s
        real(dp), intent(out) :: y(:)       !! (n)
        y = s%yh(:, 1)
    end subroutine lsoda_solution

    !> Start forward sensitivities (see the module header): after init, before the first
    !! step.
    !!
    !! sys   [in,out] the right-hand side; its sens_point and sens_jv give the terms.
    !! s0    [in]  (n, ns) the sensitivities at t0, ns >= 1.
    !! stat  [out] STATUS_OK; LSODA_ERR_ILLEGAL_INPUT (no init, the integration has
    !!             started, a bad shape or scale); or the system's code from its terms.
    !! scale [in, optional] (ns) the size of sensitivity k against the state's: its absolute
    !!             tolerance is atol scale(k) (default 1), > 0; an atol of 0 counts as
    !!             max(rtol, the unit roundoff).
    !! error_control [in, optional] .true.: the sensitivities take part in the error test
    !!             and the order selection (default .false.: the state's steps alone).
    subroutine lsoda_sens_init(s, sys, s0, stat, scale, error_control)
        class(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: s0(:, :)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: scale(:)
        logical, intent(in), optional :: error_control
        integer :: ns, n
        s%nsn = 0
        call s%sens_init_common(s0, max(s%rtol, UROUND), stat, scale, error_control)
        if (stat%code /= STATUS_OK) return
        n = s%n
        ns = s%ns
        s%nsn = n*ns
        if (allocated(s%zh)) then
            if (size(s%zh, 1) /= s%nsn) deallocate (s%zh)
        end if
        if (.not. allocated(s%zh)) allocate (s%zh(s%nsn, LMAX_ALL))
        call realloc_vec(s%srewt, s%nsn)
        call realloc_vec(s%sacor, s%nsn)
        call realloc_vec(s%sb, s%nsn)
        call realloc_vec(s%sd, s%nsn)
        call realloc_vec(s%sjv, s%nsn)
        if (allocated(s%sdfdp)) deallocate (s%sdfdp, s%sjm, s%sinv)
        allocate (s%sdfdp(n, ns), s%sjm(n, n), s%sinv(n, n))
        s%shl0 = 0.0_dp
        s%snslp = 0
        s%shave = .false.
        s%scrate = 0.7_dp
        s%zh = 0.0_dp
        s%sacor = 0.0_dp
        s%zh(:, 1) = reshape(s0, [s%nsn])
        ! the slope at t0 (scaled by the first step in lsoda_start)
        call sens_slope(s, sys, s%t, s%yh(:, 1), stat)
        if (stat%code /= STATUS_OK) then
            call s%prefix_time(stat, s%t)
            s%ns = 0
            s%nsn = 0
        end if
    end subroutine lsoda_sens_init


    !> The sensitivities (k = 0) or their k-th derivative at t within the last step (as
    !! dense for the state; sens_dense of integrator_t checks ds first).
    !!
    !! ds   [out] (n, ns).
    !! stat [out] STATUS_OK or LSODA_ERR_ILLEGAL_INPUT (t outside the step, a bad k).
    subroutine lsoda_sens_dense_at(s, t, k, ds, stat)
        class(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: ds(:, :)
        type(status_t), intent(out) :: stat
        call interpolate(s, s%zh, s%nsn, t, k, ds, stat)     ! ds as a vector of n ns
    end subroutine lsoda_sens_dense_at

    !> v(k) = g . s_k(t) for each sensitivity column at t within the last step, from the
    !! rows of the Nordsieck array where g is not 0 (Horner's scheme on each, the same
    !! operations as sens_dense's on that row): a record's samples ask for one component
    !! or a few of the state, not for all n of every column.
    !!
    !! g    [in]  (n).
    !! v    [out] (ns).
    !! stat [out] STATUS_OK or LSODA_ERR_ILLEGAL_INPUT (no sensitivities, t outside the
    !!            step, a bad shape).
    subroutine lsoda_sens_dense_dot(s, t, g, v, stat)
        class(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: t
        real(dp), intent(in) :: g(:)
        real(dp), intent(out) :: v(:)
        type(status_t), intent(out) :: stat
        real(dp) :: sc, acc, x
        integer :: nz(s%n), nnz, i, j, k, r
        v = 0.0_dp
        stat%code = STATUS_OK
        if (.not. s%ready .or. s%ns == 0 .or. size(g) /= s%n .or. size(v) /= s%ns) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda sens_dense_dot: no '// &
                'sensitivities, or g is not of n or v not of ns')
            return
        end if
        call s%check_in_step(t, 'sens_dense_dot', stat)
        if (stat%code /= STATUS_OK) return
        nnz = 0
        do i = 1, s%n
            if (g(i) /= 0.0_dp) then
                nnz = nnz + 1
                nz(nnz) = i
            end if
        end do
        sc = 0.0_dp
        if (s%h /= 0.0_dp) sc = (t - s%t)/s%h
        ! each row g needs, by Horner's scheme (as horner's), then its share of g . s_k
        do k = 1, s%ns
            acc = 0.0_dp
            do i = 1, nnz
                r = (k - 1)*s%n + nz(i)
                x = s%zh(r, s%nq + 1)
                do j = s%nq, 1, -1
                    x = s%zh(r, j) + sc*x
                end do
                acc = acc + g(nz(i))*x
            end do
            v(k) = acc
        end do
    end subroutine lsoda_sens_dense_dot

    !> v(k, o) = g(:, o) . s_k(t) for several vectors g(:, o) at once (a rate instrument's
    !! three axes): each row of the Nordsieck array that any of them needs is interpolated
    !! once (Horner's scheme, as sens_dense_dot) and shared; each column's sum takes the
    !! rows where its g is not 0 in increasing order, as sens_dense_dot's does, so that
    !! v(:, o) is sens_dense_dot's for g(:, o) to the last bit.
    !!
    !! g    [in]  (n, m).
    !! v    [out] (ns, m).
    !! stat [out] as sens_dense_dot.
    subroutine lsoda_sens_dense_dots(s, t, g, v, stat)
        class(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: t
        real(dp), intent(in) :: g(:, :)
        real(dp), intent(out) :: v(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: sc, x, acc(size(g, 2))
        integer :: nz(s%n), nnz, i, j, k, r, o, m
        v = 0.0_dp
        stat%code = STATUS_OK
        m = size(g, 2)
        if (.not. s%ready .or. s%ns == 0 .or. size(g, 1) /= s%n .or. size(v, 1) /= s%ns &
            .or. size(v, 2) /= m) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda sens_dense_dots: no '// &
                'sensitivities, or g is not of n rows or v not of ns x size(g, 2)')
            return
        end if
        call s%check_in_step(t, 'sens_dense_dots', stat)
        if (stat%code /= STATUS_OK) return
        nnz = 0
        do i = 1, s%n
            if (any(g(i, :) /= 0.0_dp)) then
                nnz = nnz + 1
                nz(nnz) = i
            end if
        end do
        sc = 0.0_dp
        if (s%h /= 0.0_dp) sc = (t - s%t)/s%h
        do k = 1, s%ns
            acc = 0.0_dp
            do i = 1, nnz
                r = (k - 1)*s%n + nz(i)
                x = s%zh(r, s%nq + 1)
                do j = s%nq, 1, -1
                    x = s%zh(r, j) + sc*x
                end do
                do o = 1, m
                    if (g(nz(i), o) /= 0.0_dp) acc(o) = acc(o) + g(nz(i), o)*x
                end do
            end do
            v(k, :) = acc
        end do
    end subroutine lsoda_sens_dense_dots
    ! ------------------------------------------------------------------------------------
    ! What integrate and step call (integrator_t's start, one_step, at_tcrit)
    ! ------------------------------------------------------------------------------------

    !> Choose the first step size (LSODE/LSODA rule) and scale yh(:,2) = h0*f0.
    subroutine lsoda_start(s, sys, tout, have_tout, stat)
        class(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: tout
        logical, intent(in) :: have_tout
        type(status_t), intent(out) :: stat
        real(dp) :: tdist, w0, tol, sm, h0, rh
        integer :: i
        character(len=160) :: buf

        stat%code = STATUS_OK
        call unused(sys)
        call update_weights(s, stat)
        if (stat%code /= STATUS_OK) return
        if (s%h0_user > 0.0_dp) then
            h0 = s%h0_user
        else
            if (have_tout) then
                tdist = abs(tout - s%t)
                w0 = max(abs(s%t), abs(tout))
                if (tdist < 2.0_dp*UROUND*w0) then
                    write (buf, '(a,es13.5e3,a)') 'lsoda: tout is too close to t0 = ', s%t, &
                        ' to start the integration'
                    call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
                    return
                end if
            else
                tdist = huge(1.0_dp)
                w0 = max(abs(s%t), 1.0_dp)
            end if
            tol = s%rtol
            if (tol <= 0.0_dp) then
                do i = 1, s%n
                    if (s%yh(i, 1) /= 0.0_dp) tol = max(tol, s%atol(i)/abs(s%yh(i, 1)))
                end do
            end if
            tol = min(max(tol, 100.0_dp*UROUND), 0.001_dp)
            sm = vmnorm(s%n, s%yh(:, 2), s%rewt)
            ! h0 = 1/sqrt(1/(tol w0^2) + tol |f|^2); for a tiny w0 (an interval of 1e-280),
            ! where w0^2 underflows to 0 and 1/w0^2 overflows, as sqrt(tol) w0 / hypot(1,
            ! tol w0 |f|), equal in exact arithmetic (the first form elsewhere: its last
            ! bits decide the step counts on the standard problems)
            if (w0 > 1.0e-100_dp .and. sm < 1.0e100_dp) then
                sm = 1.0_dp/(tol*w0*w0) + tol*sm**2
                h0 = min(1.0_dp/sqrt(sm), tdist)
            else
                h0 = min(sqrt(tol)*w0/hypot(1.0_dp, tol*w0*sm), tdist)
            end if
        end if
        rh = h0*s%hmxi
        if (rh > 1.0_dp) h0 = h0/rh
        h0 = sign(h0, s%dir)
        if (s%have_tcrit) then
            if ((s%t + h0 - s%tcrit)*h0 > 0.0_dp) h0 = (s%tcrit - s%t)*(1.0_dp - 4.0_dp*UROUND)
        end if
        s%h = h0
        s%yh(:, 2) = h0*s%yh(:, 2)
        if (s%ns > 0) s%zh(:, 2) = h0*s%zh(:, 2)
        s%jstart = JS_FIRST
        s%started = .true.
    end subroutine lsoda_start

    !> True when t is at tcrit up to roundoff.
    pure logical function lsoda_at_tcrit(s) result(at)
        class(lsoda_t), intent(in) :: s
        at = abs(s%t - s%tcrit) <= 100.0_dp*UROUND*(abs(s%t) + abs(s%h))
    end function lsoda_at_tcrit

    !> One accepted step: the checks before it (error weights, the accuracy asked, a step
    !! cut to end at tcrit), the step (take_step), and the bookkeeping after it; a failure
    !! explained in stat.
    subroutine lsoda_one_step(s, sys, stat)
        class(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(out) :: stat
        real(dp) :: tnext
        character(len=200) :: buf

        stat%code = STATUS_OK
        if (s%nst > 0) then
            call update_weights(s, stat)
            if (stat%code /= STATUS_OK) return
        end if
        if (s%have_tcrit .and. s%jstart /= JS_FIRST) then
            tnext = s%t + s%h*(1.0_dp + 4.0_dp*UROUND)
            if ((tnext - s%tcrit)*s%h > 0.0_dp) then
                s%h = (s%tcrit - s%t)*(1.0_dp - 4.0_dp*UROUND)
                if (s%jstart > 0) s%jstart = JS_NEW_H
            end if
        end if

        call take_step(s, sys, stat)

        select case (s%kflag)
        case (KF_OK)
            if (s%meth /= s%mused) then
                s%nswitch = s%nswitch + 1
                s%jstart = JS_SWITCHED
            end if
            ! A step cut short to end at tcrit lands there only up to roundoff (it is cut
            ! to (tcrit - t)*(1 - 4 u) so as never to pass it): it has reached tcrit, and
            ! says so, or a caller stepping until t_current >= tcrit would ask for a step
            ! that no longer fits (a body at rest takes one step straight to tcrit).
            if (s%have_tcrit) then
                if (lsoda_at_tcrit(s)) s%t = s%tcrit
            end if
        case (KF_ERRTEST)
            write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: error test failed repeatedly at t = ', &
                s%t, ' with |h| = ', abs(s%h)
            call set_error(stat, LSODA_ERR_ERROR_TEST, trim(buf)//' (discontinuity or '// &
                'singularity of f?)')
        case (KF_CONV)
            write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: corrector failed to converge '// &
                'repeatedly at t = ', s%t, ' with |h| = ', abs(s%h)
            call set_error(stat, LSODA_ERR_CONVERGENCE, trim(buf))
        case (KF_SINGULAR)
            write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: iteration matrix I - h*l0*J '// &
                'singular repeatedly at t = ', s%t, ' with |h| = ', abs(s%h)
            call set_error(stat, LSODA_ERR_SINGULAR, trim(buf))
        case default
            ! KF_FATAL: stat already set (rhs/jacobian failure, prefixed with the time)
            continue
        end select
    end subroutine lsoda_one_step

    !> Error weights from the current solution: rewt = 1/(rtol*|y| + atol) (and the
    !! sensitivities'); then LSODA_ERR_TOO_MUCH_ACCURACY when the accuracy asked for is
    !! beyond the machine's (u ||y|| > 0.01 in these weights).
    subroutine update_weights(s, stat)
        type(lsoda_t), intent(inout) :: s
        type(status_t), intent(inout) :: stat
        integer :: i
        character(len=160) :: buf
        call weights(s%n, s%rtol, s%yh(:, 1), s%atol, s%rewt, i)
        if (i > 0) then
            write (buf, '(a,i0,a,es15.7e3,a)') 'lsoda: error weight of component ', i, &
                ' became zero at t = ', s%t, ' (atol(i) = 0 and y(i) = 0)'
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        if (s%ns > 0) call sens_weights(s%nsn, s%rtol, s%zh(:, 1), s%satol, s%srewt)
        if (UROUND*vmnorm(s%n, s%yh(:, 1), s%rewt) > 0.01_dp) call too_much_accuracy(s, stat)
    end subroutine update_weights

    !> rewt = 1/(rtol |y| + atol), component by component up to the first whose weight is
    !! not > 0 (bad = its index, rewt kept from there on), else bad = 0.
    pure subroutine weights(n, rtol, y, atol, rewt, bad)
        integer, intent(in) :: n
        real(dp), intent(in) :: rtol, y(n), atol(n)
        real(dp), intent(inout) :: rewt(n)
        integer, intent(out) :: bad
        real(dp) :: w
        integer :: i
        bad = 0
        do i = 1, n
            w = rtol*abs(y(i)) + atol(i)
            if (.not. (w > 0.0_dp)) then
                bad = i
                return
            end if
            rewt(i) = 1.0_dp/w
        end do
    end subroutine weights

    !> The sensitivities' reciprocal weights srewt = 1/(rtol |z| + satol) (satol > 0).
    pure subroutine sens_weights(n, rtol, z, satol, srewt)
        integer, intent(in) :: n
        real(dp), intent(in) :: rtol, z(n), satol(n)
        real(dp), intent(out) :: srewt(n)
        srewt = 1.0_dp/(rtol*abs(z) + satol)
    end subroutine sens_weights

    !> LSODA_ERR_TOO_MUCH_ACCURACY at t, with the factor by which the tolerances must grow.
    subroutine too_much_accuracy(s, stat)
        type(lsoda_t), intent(in) :: s
        type(status_t), intent(inout) :: stat
        character(len=200) :: buf
        write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: too much accuracy requested for the '// &
            'machine precision at t = ', s%t, '; scale the tolerances up by at least ', &
            200.0_dp*UROUND*vmnorm(s%n, s%yh(:, 1), s%rewt)
        call set_error(stat, LSODA_ERR_TOO_MUCH_ACCURACY, trim(buf))
    end subroutine too_much_accuracy

    ! ------------------------------------------------------------------------------------
    ! The step: take_step and its parts
    ! ------------------------------------------------------------------------------------

    !> One step of the current method, in named parts: the step's start by jstart
    !! (begin_step), then attempts until one passes or the step fails.  An attempt is the
    !! prediction (predict), the corrector (correct) and the local error test
    !! (error_estimate, with the sensitivities' corrector, sens_correct); a pass is accepted
    !! (accept: the step's bookkeeping, a switch of method considered, consider_switch, else
    !! the order and step size of the next step, choose_next), a failure retried
    !! (retry_after_convergence_failure, retry_after_error_test: a smaller h, a lower
    !! order, or the end of the step with kflag).  Sets s%kflag (KF_*).  On failure t and yh
    !! are as before the call.
    subroutine take_step(s, sys, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(inout) :: stat
        integer :: ncf, m, outcome
        real(dp) :: del, dsm, pnorm, rm
        logical :: done

        s%kflag = KF_OK
        s%told = s%t
        ncf = 0
        s%jcur = .false.
        call begin_step(s)
        attempt: do
            call predict(s, pnorm)
            call correct(s, sys, pnorm, outcome, m, del, stat)
            if (outcome == CORR_FATAL) return       ! f or J failed (fail_fatal undid the step)
            if (outcome /= CORR_CONVERGED) then
                call retry_after_convergence_failure(s, outcome, ncf, done)
                if (done) exit attempt
                cycle attempt
            end if
            s%jcur = .false.
            dsm = error_estimate(s, m, del)
            ! the sensitivities at the converged point: after the error test, or before it
            ! when they take part in it
            if (s%ns > 0 .and. (s%sens_errcon .or. dsm <= 1.0_dp)) then
                call sens_correct(s, sys, stat)
                if (stat%code /= STATUS_OK) then
                    call fail_fatal(s, stat)
                    return
                end if
                if (s%sens_errcon) dsm = max(dsm, vmnorm(s%nsn, s%sacor, s%srewt)/ &
                                                  s%tesco(2, s%nq, s%meth))
            end if
            if (dsm <= 1.0_dp) then
                call accept(s, dsm, pnorm)
                exit attempt
            end if
            call retry_after_error_test(s, sys, dsm, done, stat)
            if (done) exit attempt
        end do attempt

        if (s%kflag == KF_OK) then
            rm = 1.0_dp/s%tesco(2, s%nqu, s%mused)
            call scale_vec(s%n, rm, s%acor)
        end if
        s%hold = s%h
        s%jstart = JS_GOING
    end subroutine take_step

    !> The start of a step by jstart: on the first step order 1 and the method's
    !! coefficients, with the counters of the method's state anew; after a switch of method
    !! the new method's coefficients and a new P; and yh rescaled to an h changed since the
    !! last step (after a switch, or by the driver for tcrit).
    subroutine begin_step(s)
        type(lsoda_t), intent(inout) :: s
        real(dp) :: rh
        select case (s%jstart)
        case (JS_FIRST)
            s%meth = s%meth0
            s%lmax = s%mxordn + 1
            if (s%meth == METHOD_BDF) s%lmax = s%mxords + 1
            s%nq = 1
            s%l = 2
            s%ialth = 2
            s%rmax = 1.0e4_dp
            s%rc = 0.0_dp
            s%el0 = 1.0_dp
            s%crate = 0.7_dp
            s%hold = s%h
            s%nslp = 0
            s%ipup = .false.
            s%icount = SWITCH_WAIT
            s%irflag = 0
            s%pdest = 0.0_dp
            s%pdlast = 0.0_dp
            call load_el(s)
        case (JS_SWITCHED)
            s%ipup = s%meth == METHOD_BDF
            if (s%meth == METHOD_BDF) then
                s%lmax = s%mxords + 1
            else
                s%lmax = s%mxordn + 1
            end if
            if (s%ialth == 1) s%ialth = 2
            if (s%meth /= s%mused) then
                call load_el(s)
                s%ialth = s%l
            end if
            if (s%h /= s%hold) then
                rh = s%h/s%hold
                s%h = s%hold
                call rescale(s, rh, .false.)
            end if
        case (JS_NEW_H)
            if (s%h /= s%hold) then
                rh = s%h/s%hold
                s%h = s%hold
                call rescale(s, rh, .false.)
            end if
        case default
            continue
        end select
    end subroutine begin_step

    !> The prediction: t advanced by h, the Nordsieck arrays (the state's and the
    !! sensitivities') times the Pascal triangle (the Taylor predictor to t + h), and
    !! pnorm, the weighted norm of the predicted solution.
    subroutine predict(s, pnorm)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(out) :: pnorm
        s%t = s%t + s%h
        call pascal(s%yh, s%n, s%nq)
        if (s%ns > 0) call pascal(s%zh, s%nsn, s%nq)
        pnorm = vmnorm(s%n, s%yh(:, 1), s%rewt)
    end subroutine predict

    !> The corrector at the predicted point: up to MAXCOR iterations (Adams: functional;
    !! BDF: chord Newton with P, formed anew when it is old, h l0 has drifted by more than
    !! CCMAX, or a failed iteration ran on an old one) until the estimated error of the
    !! iterate passes the convergence test.  Keeps the Lipschitz estimate pdest of the
    !! Adams iteration.
    !!
    !! pnorm   [in]  weighted norm of the predicted solution.
    !! outcome [out] CORR_CONVERGED (y, savf, acor the converged point), CORR_DIVERGED,
    !!               CORR_SINGULAR (P singular), CORR_UNSOLVED (the solve with P failed) or
    !!               CORR_FATAL (f or J failed: stat says why, and the step is undone).
    !! m       [out] the iterations after the first.
    !! del     [out] the weighted norm of the last change of the iterate.
    subroutine correct(s, sys, pnorm, outcome, m, del, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: pnorm
        integer, intent(out) :: outcome, m
        real(dp), intent(out) :: del
        type(status_t), intent(inout) :: stat
        real(dp) :: delp, rate, rm, dcon
        logical :: newton, singular

        newton = s%meth == METHOD_BDF
        if (abs(s%rc - 1.0_dp) > CCMAX) s%ipup = newton
        if (s%nst >= s%nslp + MSBP) s%ipup = newton
        outcome = CORR_DIVERGED
        delp = 0.0_dp
        corrector: do
            m = 0
            rate = 0.0_dp
            del = 0.0_dp
            call copy_vec(s%n, s%yh(:, 1), s%y)
            call corrector_rhs(s, sys, stat)
            if (stat%code /= STATUS_OK) then
                outcome = CORR_FATAL
                return
            end if
            if (s%ipup) then
                call build_iteration_matrix(s, sys, stat, singular)
                if (stat%code /= STATUS_OK) then
                    call fail_fatal(s, stat)
                    outcome = CORR_FATAL
                    return
                end if
                s%ipup = .false.
                s%rc = 1.0_dp
                s%nslp = s%nst
                s%crate = 0.7_dp
                if (singular) then
                    outcome = CORR_SINGULAR
                    return
                end if
            end if
            s%acor = 0.0_dp
            iterate: do
                call corrector_update(s, sys, newton, del, stat)
                if (stat%code /= STATUS_OK) then
                    outcome = CORR_UNSOLVED        ! cannot happen with consistent shapes
                    return
                end if
                ! convergence test; at least two iterations for Adams (Lipschitz estimate)
                if (del <= 100.0_dp*pnorm*UROUND) then
                    outcome = CORR_CONVERGED
                    return
                end if
                if (m > 0 .or. newton) then
                    if (m > 0) then
                        rm = 1024.0_dp
                        if (del <= 1024.0_dp*delp) rm = del/delp
                        rate = max(rate, rm)
                        s%crate = max(0.2_dp*s%crate, rm)
                    end if
                    dcon = del*min(1.0_dp, 1.5_dp*s%crate)/ &
                        (s%tesco(2, s%nq, s%meth)*s%conit)
                    if (dcon <= 1.0_dp) then
                        s%pdest = max(s%pdest, rate/abs(s%h*s%el(1)))
                        if (s%pdest /= 0.0_dp) s%pdlast = s%pdest
                        outcome = CORR_CONVERGED
                        return
                    end if
                end if
                m = m + 1
                if (m == MAXCOR) exit iterate
                if (m >= 2 .and. del > 2.0_dp*delp) exit iterate
                delp = del
                call corrector_rhs(s, sys, stat)
                if (stat%code /= STATUS_OK) then
                    outcome = CORR_FATAL
                    return
                end if
            end do iterate
            ! the iteration failed: retry once with a fresh matrix if it was old
            if (.not. newton .or. s%jcur) return
            s%ipup = .true.
        end do corrector
    end subroutine correct

    !> f at the corrector's iterate y (savf), counted; on a failure the step is undone
    !! (fail_fatal) and stat says why.
    subroutine corrector_rhs(s, sys, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(inout) :: stat
        call sys%rhs(s%t, s%y, s%savf, stat)
        s%nfe = s%nfe + 1
        if (stat%code /= STATUS_OK) call fail_fatal(s, stat)
    end subroutine corrector_rhs

    !> One update of the corrector's iterate y from f at it (savf): the functional
    !! iteration (Adams) or a chord Newton step with P (BDF); acor the correction so far,
    !! del the weighted norm of this update.  stat: a failure of the solve with P.
    subroutine corrector_update(s, sys, newton, del, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        logical, intent(in) :: newton               !! BDF: chord Newton
        real(dp), intent(out) :: del
        type(status_t), intent(inout) :: stat
        if (.not. newton) then
            call functional_update(s%n, s%h, s%el(1), s%yh(:, 1), s%yh(:, 2), &
                                   s%rewt, s%savf, s%acor, s%y, del)
            return
        end if
        del = 0.0_dp
        call newton_residual(s%n, s%h, s%savf, s%yh(:, 2), s%acor, s%y)
        if (s%structured) then
            call sys%solve_iteration(s%y, stat)
        else
            call la_lu_solve(s%wm, s%ipiv, s%y, stat)
        end if
        if (stat%code /= STATUS_OK) return
        call newton_update(s%n, s%el(1), s%yh(:, 1), s%rewt, s%acor, s%y, del)
    end subroutine corrector_update

    !> The local error test's norm of the converged step's error estimate: the weighted
    !! norm of acor (del when the first iteration converged) over the method's divisor.
    pure real(dp) function error_estimate(s, m, del) result(dsm)
        type(lsoda_t), intent(in) :: s
        integer, intent(in) :: m                    !! the corrector's iterations after the first
        real(dp), intent(in) :: del                 !! the norm of its last change
        if (m == 0) then
            dsm = del/s%tesco(2, s%nq, s%meth)
        else
            dsm = vmnorm(s%n, s%acor, s%rewt)/s%tesco(2, s%nq, s%meth)
        end if
    end function error_estimate

    !> After a corrector that did not converge: undo the prediction and retry with h/4 and a
    !! new P, or end the step (done, kflag KF_CONV or KF_SINGULAR) when h is at its floor,
    !! after MXNCF such failures, or when the solve with P failed.
    subroutine retry_after_convergence_failure(s, outcome, ncf, done)
        type(lsoda_t), intent(inout) :: s
        integer, intent(in) :: outcome              !! correct's (not CORR_CONVERGED)
        integer, intent(inout) :: ncf               !! convergence failures of this step
        logical, intent(out) :: done                !! the step ends (kflag set)
        ncf = ncf + 1
        s%ncfn = s%ncfn + 1
        s%rmax = 2.0_dp
        s%t = s%told
        call unpredict(s)
        done = .true.
        if (outcome == CORR_UNSOLVED) then
            s%kflag = KF_SINGULAR
            return
        end if
        if (abs(s%h) <= max(HMIN*1.00001_dp, hfloor(s)) .or. ncf == MXNCF) then
            s%kflag = KF_CONV
            if (outcome == CORR_SINGULAR) s%kflag = KF_SINGULAR
            return
        end if
        done = .false.
        s%ipup = s%meth == METHOD_BDF
        call rescale(s, 0.25_dp, .true.)
    end subroutine retry_after_convergence_failure

    !> After a failed local error test (dsm > 1): undo the prediction and retry at the order
    !! and h choose_order gives, after the third failure of the step at order 1 with h/10
    !! from f anew, or end the step (done, kflag KF_ERRTEST) when h is at its floor or after
    !! MXNEF failures (KF_FATAL when f failed: stat says why).
    subroutine retry_after_error_test(s, sys, dsm, done, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: dsm                 !! the error test's norm
        logical, intent(out) :: done                !! the step ends (kflag set)
        type(status_t), intent(inout) :: stat
        real(dp) :: rh
        integer :: newq
        s%netf = s%netf + 1
        s%kflag = s%kflag - 1
        s%t = s%told
        call unpredict(s)
        s%rmax = 2.0_dp
        done = .true.
        if (abs(s%h) <= max(HMIN*1.00001_dp, hfloor(s))) then
            s%kflag = KF_ERRTEST
            return
        end if
        if (s%kflag <= -3) then
            if (s%kflag <= -MXNEF) then
                s%kflag = KF_ERRTEST
                return
            end if
            ! repeated failures: restart at order 1 from a fresh derivative, h/10
            rh = max(HMIN/abs(s%h), 0.1_dp)
            s%h = s%h*rh
            s%y = s%yh(:, 1)
            call sys%rhs(s%t, s%y, s%savf, stat)
            s%nfe = s%nfe + 1
            if (stat%code /= STATUS_OK) then
                call s%prefix_time(stat, s%t)
                s%kflag = KF_FATAL
                return
            end if
            s%yh(:, 2) = s%h*s%savf
            if (s%ns > 0) then
                call sens_slope(s, sys, s%t, s%y, stat)
                if (stat%code /= STATUS_OK) then
                    call s%prefix_time(stat, s%t)
                    s%kflag = KF_FATAL
                    return
                end if
                s%zh(:, 2) = s%h*s%zh(:, 2)
            end if
            s%ipup = s%meth == METHOD_BDF
            s%ialth = 5
            call set_order(s, 1)
            done = .false.
            return
        end if
        call choose_order(s, dsm, .false., newq, rh)
        call set_order(s, newq)
        call rescale(s, rh, .true.)
        done = .false.
    end subroutine retry_after_error_test

    !> The accepted step: the counters, the correction added to the Nordsieck arrays, then a
    !! switch of method considered (consider_switch: h and the order of the new method),
    !! else the order and h of the next step (choose_next).
    subroutine accept(s, dsm, pnorm)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: dsm                 !! the error test's norm (<= 1)
        real(dp), intent(in) :: pnorm               !! the predicted solution's norm
        real(dp) :: rh
        logical :: switched
        s%kflag = KF_OK
        s%nst = s%nst + 1
        s%hu = s%h
        s%nqu = s%nq
        s%mused = s%meth
        call add_correction(s%yh, s%n, s%el, s%acor, s%l)
        if (s%ns > 0) call add_correction(s%zh, s%nsn, s%el, s%sacor, s%l)
        call consider_switch(s, dsm, pnorm, switched, rh)
        if (switched) then
            s%icount = SWITCH_WAIT
            s%pdlast = 0.0_dp
            s%l = s%nq + 1
            call rescale(s, rh, .true.)
            s%rmax = 10.0_dp
            return
        end if
        call choose_next(s, dsm)
    end subroutine accept

    !> Every SWITCH_WAIT steps after the last switch, on every accepted step: would the
    !! other method take a step enough larger (Adams -> BDF: 5 times, within Adams'
    !! stability region; BDF -> Adams: not smaller) at the same accuracy?  If so, switched,
    !! meth and nq are the new method and order and rh the ratio of its step to h.
    subroutine consider_switch(s, dsm, pnorm, switched, rh)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: dsm, pnorm          !! the error test's norm, the prediction's
        logical, intent(out) :: switched
        real(dp), intent(out) :: rh
        switched = .false.
        rh = 1.0_dp
        s%icount = s%icount - 1
        if (s%icount >= 0) return
        if (s%meth == METHOD_ADAMS) then
            call test_switch_to_bdf(s, dsm, pnorm, switched, rh)
        else
            call test_switch_to_adams(s, dsm, pnorm, switched, rh)
        end if
    end subroutine consider_switch

    !> Adams -> BDF: the step BDF could take at the same accuracy, rh2 h, against Adams'
    !! rh1 h (held to its stability region by the Lipschitz estimate pdlast); a switch when
    !! rh2 >= SWITCH_RATIO rh1, or when the step is held by stability while its error is
    !! negligible.  Never with adams_only, nor above order 5.
    subroutine test_switch_to_bdf(s, dsm, pnorm, switched, rh)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: dsm, pnorm
        logical, intent(inout) :: switched
        real(dp), intent(inout) :: rh
        real(dp) :: exsm, rh1, rh1it, rh2, pdh, dm, exm
        integer :: nqm
        if (s%nq > 5 .or. s%adams_only) return
        rh2 = 1.0_dp
        nqm = 1
        if (dsm > 100.0_dp*pnorm*UROUND .and. s%pdest /= 0.0_dp) then
            exsm = 1.0_dp/s%l
            rh1 = 1.0_dp/(1.2_dp*dsm**exsm + 1.2e-6_dp)
            rh1it = 2.0_dp*rh1
            pdh = s%pdlast*abs(s%h)
            if (pdh*rh1 > 1.0e-5_dp) rh1it = SM1(s%nq)/pdh
            rh1 = min(rh1, rh1it)
            call other_method_step(s, dsm, s%mxords, s%cm1, s%cm2, nqm, dm, exm, rh2)
            if (rh2 >= SWITCH_RATIO*rh1) switched = .true.
        else if (s%irflag /= 0) then
            ! step limited by stability yet error tiny: go stiff
            rh2 = 2.0_dp
            nqm = min(s%nq, s%mxords)
            switched = .true.
        end if
        if (switched) then
            rh = rh2
            s%meth = METHOD_BDF
            s%nq = nqm
        end if
    end subroutine test_switch_to_bdf

    !> BDF -> Adams: the step Adams could take at the same accuracy, within its stability
    !! region (pdnorm, the norm of J), rh1 h, against BDF's rh2 h; a switch when Adams' is
    !! not smaller and its error estimate is not lost in roundoff.
    subroutine test_switch_to_adams(s, dsm, pnorm, switched, rh)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: dsm, pnorm
        logical, intent(inout) :: switched
        real(dp), intent(inout) :: rh
        real(dp) :: exsm, rh1, rh1it, rh2, pdh, dm, exm, alpha
        integer :: nqm
        exsm = 1.0_dp/s%l
        call other_method_step(s, dsm, s%mxordn, s%cm2, s%cm1, nqm, dm, exm, rh1)
        rh1it = 2.0_dp*rh1
        pdh = s%pdnorm*abs(s%h)
        if (pdh*rh1 > 1.0e-5_dp) rh1it = SM1(nqm)/pdh
        rh1 = min(rh1, rh1it)
        rh2 = 1.0_dp/(1.2_dp*dsm**exsm + 1.2e-6_dp)
        if (rh1*SWITCH_RATIO >= 5.0_dp*rh2) then
            alpha = max(0.001_dp, rh1)
            dm = alpha**exm*dm
            if (dm > 1000.0_dp*UROUND*pnorm) then
                switched = .true.
                rh = rh1
                s%meth = METHOD_ADAMS
                s%nq = nqm
            end if
        end if
    end subroutine test_switch_to_adams

    !> The step the other method could take at the same accuracy, rh h (the switching
    !! tests): at order nqm = min(nq, its highest order), from this step's error norm dsm
    !! scaled by the two methods' error constants, or, above its highest order, from yh's
    !! column nqm + 2 (dm the error estimate, exm = 1/(nqm + 1)).
    subroutine other_method_step(s, dsm, mxord_other, cm_this, cm_other, nqm, dm, exm, rh)
        type(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: dsm                 !! this step's error norm
        integer, intent(in) :: mxord_other          !! the other method's highest order
        real(dp), intent(in) :: cm_this(:), cm_other(:)     !! their constants (cm1, cm2)
        integer, intent(out) :: nqm
        real(dp), intent(out) :: dm, exm, rh
        integer :: lm
        if (s%nq > mxord_other) then
            nqm = mxord_other
            lm = nqm + 1
            exm = 1.0_dp/lm
            dm = vmnorm(s%n, s%yh(:, lm + 1), s%rewt)/cm_other(nqm)
            rh = 1.0_dp/(1.2_dp*dm**exm + 1.2e-6_dp)
        else
            exm = 1.0_dp/s%l
            dm = dsm*(cm_this(s%nq)/cm_other(s%nq))
            rh = 1.0_dp/(1.2_dp*dm**exm + 1.2e-6_dp)
            nqm = s%nq
        end if
    end subroutine other_method_step

    !> The order and h of the step after an accepted one without a switch: every ialth
    !! steps choose_order's, with yh rescaled to the new h; on the step before that,
    !! acor kept in yh's last column for its test of the order above.
    subroutine choose_next(s, dsm)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: dsm                 !! the error test's norm
        real(dp) :: rh
        integer :: newq
        s%ialth = s%ialth - 1
        if (s%ialth == 0) then
            call choose_order(s, dsm, .true., newq, rh)
            if (newq < 0) return                    ! keep order and step
            call set_order(s, newq)
            call rescale(s, rh, .true.)
            s%rmax = 10.0_dp
            return
        end if
        if (s%ialth == 1 .and. s%l /= s%lmax) then
            s%yh(:, s%lmax) = s%acor                ! kept for the order-increase test
            if (s%ns > 0) s%zh(:, s%lmax) = s%sacor
        end if
    end subroutine choose_next

    !> The order nq (l = nq + 1) and its coefficients, when it changes.
    subroutine set_order(s, newq)
        type(lsoda_t), intent(inout) :: s
        integer, intent(in) :: newq
        if (newq == s%nq) return
        s%nq = newq
        s%l = newq + 1
        call load_el(s)
    end subroutine set_order

    !> Undo the prediction after a right-hand-side failure and mark the step fatal.
    subroutine fail_fatal(s, stat)
        type(lsoda_t), intent(inout) :: s
        type(status_t), intent(inout) :: stat
        s%t = s%told
        call unpredict(s)
        call s%prefix_time(stat, s%t)
        s%kflag = KF_FATAL
        s%hold = s%h
    end subroutine fail_fatal

    !> Smallest |h| worth trying at t (a few units of roundoff of t).
    pure real(dp) function hfloor(s)
        type(lsoda_t), intent(in) :: s
        hfloor = 4.0_dp*UROUND*abs(s%t)
    end function hfloor

    !> Order and step-size ratio for the next step (after a success: orders nq-1, nq,
    !! nq+1; after an error-test failure: nq-1, nq).  newq = -1: keep order and step
    !! (increase below 10 %), with ialth set to retry the test in 3 steps.
    subroutine choose_order(s, dsm, success, newq, rh)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: dsm
        logical, intent(in) :: success
        integer, intent(out) :: newq
        real(dp), intent(out) :: rh
        real(dp) :: rhup, rhsm, rhdn, dup, ddn, pdh
        integer :: i, lmx

        rhup = 0.0_dp
        lmx = s%lmax
        if (success .and. s%l /= lmx) then
            do i = 1, s%n
                s%savf(i) = s%acor(i) - s%yh(i, lmx)
            end do
            dup = vmnorm(s%n, s%savf, s%rewt)/s%tesco(3, s%nq, s%meth)
            if (s%ns > 0 .and. s%sens_errcon) dup = max(dup, vmnorm_diff(s%nsn, s%sacor, &
                s%zh(:, lmx), s%srewt)/s%tesco(3, s%nq, s%meth))
            rhup = 1.0_dp/(1.4_dp*dup**(1.0_dp/(s%l + 1)) + 1.4e-6_dp)
        end if
        rhsm = 1.0_dp/(1.2_dp*dsm**(1.0_dp/s%l) + 1.2e-6_dp)
        rhdn = 0.0_dp
        if (s%nq /= 1) then
            ddn = vmnorm(s%n, s%yh(:, s%l), s%rewt)/s%tesco(1, s%nq, s%meth)
            if (s%ns > 0 .and. s%sens_errcon) ddn = max(ddn, vmnorm(s%nsn, s%zh(:, s%l), &
                s%srewt)/s%tesco(1, s%nq, s%meth))
            rhdn = 1.0_dp/(1.3_dp*ddn**(1.0_dp/s%nq) + 1.3e-6_dp)
        end if
        pdh = 0.0_dp
        if (s%meth == METHOD_ADAMS) then
            ! Adams: stay inside the stability region
            pdh = max(abs(s%h)*s%pdlast, 1.0e-6_dp)
            if (s%l < lmx) rhup = min(rhup, SM1(s%l)/pdh)
            rhsm = min(rhsm, SM1(s%nq)/pdh)
            if (s%nq > 1) rhdn = min(rhdn, SM1(s%nq - 1)/pdh)
            s%pdest = 0.0_dp
        end if
        if (rhsm >= rhup) then
            if (rhsm >= rhdn) then
                newq = s%nq
                rh = rhsm
            else
                newq = s%nq - 1
                rh = rhdn
                if (s%kflag < 0 .and. rh > 1.0_dp) rh = 1.0_dp
            end if
        else if (rhup > rhdn) then
            ! order increase
            newq = s%l
            rh = rhup
            if (rh < 1.1_dp) then
                s%ialth = 3
                newq = -1
                return
            end if
            do i = 1, s%n
                s%yh(i, newq + 1) = s%acor(i)*(s%el(s%l)/s%l)
            end do
            if (s%ns > 0) s%zh(:, newq + 1) = s%sacor*(s%el(s%l)/s%l)
            return
        else
            newq = s%nq - 1
            rh = rhdn
            if (s%kflag < 0 .and. rh > 1.0_dp) rh = 1.0_dp
        end if
        ! small changes are not worth it, unless Adams is held by its stability limit
        if (.not. (s%meth == METHOD_ADAMS .and. rh*pdh*1.00001_dp >= SM1(max(newq, 1)))) then
            if (s%kflag == 0 .and. rh < 1.1_dp) then
                s%ialth = 3
                newq = -1
                return
            end if
        end if
        if (s%kflag <= -2) rh = min(rh, 0.2_dp)
    end subroutine choose_order

    !> Coefficients of the current method and order; rc follows the change of l0.
    subroutine load_el(s)
        type(lsoda_t), intent(inout) :: s
        s%el(1:s%nq + 1) = s%elco(1:s%nq + 1, s%nq, s%meth)
        s%rc = s%rc*s%el(1)/s%el0
        s%el0 = s%el(1)
        s%conit = 0.5_dp/(s%nq + 2)
    end subroutine load_el

    !> Change h by the factor rh (bounded by rmax, hmax, hmin and, for Adams, the stability
    !! region) and rescale the Nordsieck array.
    subroutine rescale(s, rh_in, use_hmin)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: rh_in
        logical, intent(in) :: use_hmin
        real(dp) :: rh, pdh
        rh = rh_in
        if (use_hmin) rh = max(rh, HMIN/abs(s%h))
        rh = min(rh, s%rmax)
        rh = rh/max(1.0_dp, abs(s%h)*s%hmxi*rh)
        if (s%meth == METHOD_ADAMS) then
            s%irflag = 0
            pdh = max(abs(s%h)*s%pdlast, 1.0e-6_dp)
            if (rh*pdh*1.00001_dp >= SM1(s%nq)) then
                rh = SM1(s%nq)/pdh
                s%irflag = 1
            end if
        end if
        call scale_columns(s%yh, s%n, s%l, rh)
        if (s%ns > 0) call scale_columns(s%zh, s%nsn, s%l, rh)
        s%h = s%h*rh
        s%rc = s%rc*rh
        s%ialth = s%l
    end subroutine rescale

    !> yh <- yh times the Pascal triangle on columns 1 ... nq + 1, rows 1:nrow (the Taylor
    !! predictor): for k = 1 ... nq and j = nq down to k, yh(:, j) = yh(:, j) + yh(:, j + 1),
    !! each element by these additions in this order however the rows are grouped.  From
    !! order 4 up, two rows at a time with the columns held in registers c1 ... c13: the
    !! triangle of order nq is the last nq levels of the triangle of order 12, so column j goes
    !! to register j + 12 - nq and level k of the order-12 triangle (c12 down to ck) runs when
    !! nq >= 13 - k (the compiler turns these tests into one jump into the sequence per pair of
    !! rows); the registers below c13 - nq stay 0, unused.  Below order 4, and for an odd last
    !! row, column by column.
    pure subroutine pascal(yh, nrow, nq)
        integer, intent(in) :: nrow, nq                  !! rows used, order (1 ... 12)
        real(dp), intent(inout) :: yh(nrow, LMAX_ALL)    !! Nordsieck array
        real(dp), dimension(2) :: c1, c2, c3, c4, c5, c6, c7, c8, c9, c10, c11, c12, c13
        integer :: i, j, k, o
        if (nq < 4) then
            do k = 1, nq
                do j = nq, k, -1
                    yh(:, j) = yh(:, j) + yh(:, j + 1)
                end do
            end do
            return
        end if
        o = nq - 12
        c1 = 0.0_dp; c2 = 0.0_dp; c3 = 0.0_dp; c4 = 0.0_dp; c5 = 0.0_dp; c6 = 0.0_dp; c7 = 0.0_dp
        c8 = 0.0_dp
        do i = 1, nrow - 1, 2
            c13 = yh(i:i + 1, 13 + o)
            c12 = yh(i:i + 1, 12 + o)
            c11 = yh(i:i + 1, 11 + o)
            c10 = yh(i:i + 1, 10 + o)
            c9 = yh(i:i + 1, 9 + o)
            if (nq >= 5) c8 = yh(i:i + 1, 8 + o)
            if (nq >= 6) c7 = yh(i:i + 1, 7 + o)
            if (nq >= 7) c6 = yh(i:i + 1, 6 + o)
            if (nq >= 8) c5 = yh(i:i + 1, 5 + o)
            if (nq >= 9) c4 = yh(i:i + 1, 4 + o)
            if (nq >= 10) c3 = yh(i:i + 1, 3 + o)
            if (nq >= 11) c2 = yh(i:i + 1, 2 + o)
            if (nq >= 12) c1 = yh(i:i + 1, 1 + o)
            if (nq >= 12) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
                c7 = c7 + c8; c6 = c6 + c7; c5 = c5 + c6; c4 = c4 + c5; c3 = c3 + c4; c2 = c2 + c3
                c1 = c1 + c2
            end if
            if (nq >= 11) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
                c7 = c7 + c8; c6 = c6 + c7; c5 = c5 + c6; c4 = c4 + c5; c3 = c3 + c4; c2 = c2 + c3
            end if
            if (nq >= 10) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
                c7 = c7 + c8; c6 = c6 + c7; c5 = c5 + c6; c4 = c4 + c5; c3 = c3 + c4
            end if
            if (nq >= 9) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
                c7 = c7 + c8; c6 = c6 + c7; c5 = c5 + c6; c4 = c4 + c5
            end if
            if (nq >= 8) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
                c7 = c7 + c8; c6 = c6 + c7; c5 = c5 + c6
            end if
            if (nq >= 7) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
                c7 = c7 + c8; c6 = c6 + c7
            end if
            if (nq >= 6) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
                c7 = c7 + c8
            end if
            if (nq >= 5) then
                c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10; c8 = c8 + c9
            end if
            c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11; c9 = c9 + c10
            c12 = c12 + c13; c11 = c11 + c12; c10 = c10 + c11
            c12 = c12 + c13; c11 = c11 + c12
            c12 = c12 + c13
            yh(i:i + 1, 12 + o) = c12
            yh(i:i + 1, 11 + o) = c11
            yh(i:i + 1, 10 + o) = c10
            yh(i:i + 1, 9 + o) = c9
            if (nq >= 5) yh(i:i + 1, 8 + o) = c8
            if (nq >= 6) yh(i:i + 1, 7 + o) = c7
            if (nq >= 7) yh(i:i + 1, 6 + o) = c6
            if (nq >= 8) yh(i:i + 1, 5 + o) = c5
            if (nq >= 9) yh(i:i + 1, 4 + o) = c4
            if (nq >= 10) yh(i:i + 1, 3 + o) = c3
            if (nq >= 11) yh(i:i + 1, 2 + o) = c2
            if (nq >= 12) yh(i:i + 1, 1 + o) = c1
        end do
        if (mod(nrow, 2) == 1) then
            do k = 1, nq
                do j = nq, k, -1
                    yh(nrow, j) = yh(nrow, j) + yh(nrow, j + 1)
                end do
            end do
        end if
    end subroutine pascal

    !> yh(:, j) <- yh(:, j) + el(j) acor, j = 1 ... l: a step's correction added to the
    !! Nordsieck array (rows 1:nrow), two columns in one pass over acor.
    pure subroutine add_correction(yh, nrow, el, acor, l)
        integer, intent(in) :: nrow, l                   !! rows used, columns
        real(dp), intent(inout) :: yh(nrow, LMAX_ALL)    !! Nordsieck array
        real(dp), intent(in) :: el(LMAX_ALL)             !! method coefficients l_j
        real(dp), intent(in) :: acor(nrow)               !! the step's correction
        integer :: i, j
        do j = 1, l - 1, 2
            do i = 1, nrow
                yh(i, j) = yh(i, j) + el(j)*acor(i)
                yh(i, j + 1) = yh(i, j + 1) + el(j + 1)*acor(i)
            end do
        end do
        if (mod(l, 2) == 1) yh(:, l) = yh(:, l) + el(l)*acor
    end subroutine add_correction

    !> Inverse of predict.
    subroutine unpredict(s)
        type(lsoda_t), intent(inout) :: s
        call unpascal(s%yh, s%n, s%nq)
        if (s%ns > 0) call unpascal(s%zh, s%nsn, s%nq)
    end subroutine unpredict

    !> The inverse of pascal: for k = nq down to 1 and j = k ... nq,
    !! yh(:, j) = yh(:, j) - yh(:, j + 1).
    pure subroutine unpascal(yh, nrow, nq)
        integer, intent(in) :: nrow, nq                  !! rows used, order
        real(dp), intent(inout) :: yh(nrow, LMAX_ALL)    !! Nordsieck array
        integer :: j, k
        do k = nq, 1, -1
            do j = k, nq
                yh(:, j) = yh(:, j) - yh(:, j + 1)
            end do
        end do
    end subroutine unpascal

    !> yh(:, j) <- yh(:, j) r^(j-1), j = 2 ... l (rows 1:nrow), the powers of r by successive
    !! products: the Nordsieck array rescaled to the step h r.
    pure subroutine scale_columns(yh, nrow, l, r)
        integer, intent(in) :: nrow, l                   !! rows used, columns
        real(dp), intent(inout) :: yh(nrow, LMAX_ALL)    !! Nordsieck array
        real(dp), intent(in) :: r                        !! step ratio
        real(dp) :: rj
        integer :: j
        rj = 1.0_dp
        do j = 2, l
            rj = rj*r
            yh(:, j) = yh(:, j)*rj
        end do
    end subroutine scale_columns

    !> P = I - h*l0*J (J analytic or by finite differences), its LU factors, and the
    !! weighted norm of J used by the stiff -> non-stiff test.  On entry y = predicted
    !! solution and savf = f(t, y).
    subroutine build_iteration_matrix(s, sys, stat, singular)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(inout) :: stat
        logical, intent(out) :: singular
        real(dp) :: hl0, fac, r0, r, yj, srur, rowsum, pn
        integer :: i, j, n
        type(status_t) :: lst

        n = s%n
        singular = .false.
        s%nje = s%nje + 1
        s%jcur = .true.
        hl0 = s%h*s%el0
        if (s%structured) then
            ! the system forms and factors P itself (ode_system's has_iteration_solver)
            call sys%factor_iteration(s%t, s%y, hl0, s%rewt, pn, singular, stat)
            if (stat%code /= STATUS_OK) return
            s%pdnorm = pn
            s%nlu = s%nlu + 1
            return
        end if
        if (sys%has_jacobian()) then
            call sys%jacobian(s%t, s%y, s%wm, stat)
            if (stat%code /= STATUS_OK) return
            do j = 1, n
                do i = 1, n
                    s%wm(i, j) = -hl0*s%wm(i, j)
                end do
            end do
        else
            fac = vmnorm(n, s%savf, s%rewt)
            r0 = 1000.0_dp*abs(s%h)*UROUND*n*fac
            ! f = 0 (at rest): increments of one error weight, as in LSODA; the same when f
            ! is negligible (h*f below 1e-3 weights per step: r0 < UROUND), or increments of
            ! 1e-311 near an equilibrium at 1e-300 make h*l0/r overflow
            if (r0 < UROUND) r0 = 1.0_dp
            srur = sqrt(UROUND)
            do j = 1, n
                yj = s%y(j)
                r = max(srur*abs(yj), r0/s%rewt(j))
                s%y(j) = yj + r
                fac = -hl0/r
                call sys%rhs(s%t, s%y, s%ftem, stat)
                s%nfe = s%nfe + 1
                s%y(j) = yj
                if (stat%code /= STATUS_OK) return
                do i = 1, n
                    s%wm(i, j) = (s%ftem(i) - s%savf(i))*fac
                end do
            end do
        end if
        ! weighted max-row-sum norm of J: max_i w_i^-1 sum_j |J_ij| w_j
        pn = 0.0_dp
        do i = 1, n
            rowsum = 0.0_dp
            do j = 1, n
                rowsum = rowsum + abs(s%wm(i, j))/s%rewt(j)
            end do
            pn = max(pn, rowsum*s%rewt(i))
        end do
        s%pdnorm = pn/abs(hl0)
        do i = 1, n
            s%wm(i, i) = s%wm(i, i) + 1.0_dp
        end do
        s%nlu = s%nlu + 1
        call la_lu_factor(s%wm, s%ipiv, lst)
        singular = lst%code /= STATUS_OK
    end subroutine build_iteration_matrix

    !> zh(:, 2) = the sensitivities' slope J zh(:, 1) + df/dp at (t, y) (unscaled).
    subroutine sens_slope(s, sys, t, y, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        type(status_t), intent(out) :: stat
        call sys%sens_point(t, y, s%sdfdp, stat)
        s%nsp = s%nsp + 1
        if (stat%code /= STATUS_OK) return
        call sens_products(sys, s%n, s%ns, s%zh(:, 1), s%sjv, stat)
        if (stat%code /= STATUS_OK) return
        call sens_sum(s%nsn, s%sjv, s%sdfdp, s%zh(:, 2))
    end subroutine sens_slope

    !> The sensitivities' corrector at the step's converged point (t, y): sacor with
    !!     (I - h l0 J) sacor = h (J zh1 + df/dp) - zh2
    !! (zh predicted; J and df/dp exact at (t, y)), solved by a chord iteration whose
    !! residuals use the exact J: a BDF step's iteration matrix is its Newton matrix, an Adams
    !! step's the inverse of the sensitivities' own I - h l0 J (sens_matrix; kept by the
    !! Newton matrix's rules: a new one every MSBP steps or when h l0 changed by more than
    !! CCMAX).  The iteration stops, as the state's corrector, when a correction times
    !! min(1, 1.5 rate) (the iteration's rate, measured and kept from step to step) is below
    !! SENS_CONV times the state's convergence test, in the sensitivities' weights; one that
    !! contracts too slowly ends in a direct solve with I - h l0 J formed at the point.  In
    !! the error control an Adams step uses its own functional iteration instead (to
    !! SENS_CONV_EC of the state's test): there the columns are many, and Z at the point,
    !! which the products use, is at hand.  The sensitivities are thus the solution of the
    !! step's formula to that tolerance whether or not they take part in the error test.
    subroutine sens_correct(s, sys, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(inout) :: stat
        real(dp) :: hl0, del, delp, tol
        integer :: m, k, n, i0
        logical :: conv
        ! the iteration's a is sacor itself; its b, d and J a are sb, sd and sjv (vectors of
        ! n ns, the columns one after another, as zh's)
        n = s%n
        hl0 = s%h*s%el(1)
        call sys%sens_point(s%t, s%y, s%sdfdp, stat)
        s%nsp = s%nsp + 1
        if (stat%code /= STATUS_OK) return
        if (s%meth == METHOD_ADAMS .and. .not. s%sens_errcon) then
            ! the sensitivities' own matrix, first: its J makes the products below cheap
            if (.not. s%shave .or. s%nst >= s%snslp + MSBP .or. &
                abs(hl0 - s%shl0) > CCMAX*abs(s%shl0)) then
                call sens_matrix(s, sys, hl0, stat)
                if (stat%code /= STATUS_OK) return
            end if
        end if
        call sens_products(sys, n, s%ns, s%zh(:, 1), s%sjv, stat)
        if (stat%code /= STATUS_OK) return
        call sens_rhs(s%nsn, s%h, s%sjv, s%sdfdp, s%zh(:, 2), s%sb)
        tol = SENS_CONV*s%tesco(2, s%nq, s%meth)*s%conit
        conv = .false.
        delp = 0.0_dp
        if (s%sens_errcon .and. s%meth == METHOD_ADAMS) then
            ! in the error control (many columns: Z at the point is at hand) an Adams step's
            ! functional iteration a <- b + h l0 J a, from a = b, to a tenth of the state's test
            tol = SENS_CONV_EC*s%tesco(2, s%nq, s%meth)*s%conit
            s%sacor = s%sb
            do m = 1, SENS_MAXIT
                call sens_products(sys, n, s%ns, s%sacor, s%sjv, stat)
                if (stat%code /= STATUS_OK) return
                s%nsit = s%nsit + 1
                call sens_fixed_point(s%nsn, hl0, s%sb, s%sjv, s%srewt, s%sacor, del)
                if (del <= tol) then
                    conv = .true.
                    exit
                end if
                if (m > 1 .and. del > 0.5_dp*delp) exit
                delp = del
            end do
            if (.not. conv) call direct()
            return
        end if
        ! the chord iteration a <- a + P^-1 (b + h l0 J a - a), from a = 0
        s%sacor = 0.0_dp
        s%sd = s%sb
        do m = 1, SENS_MAXIT
            if (s%meth == METHOD_ADAMS) then
                ! all columns at once by the inverse (sjv is free until the next products)
                call inverse_times(n, s%ns, s%sinv, s%sd, s%sjv)
                s%nsit = s%nsit + 1
                call sens_accumulate(s%nsn, s%sjv, s%srewt, s%sacor, del)
            else
                do k = 1, s%ns
                    i0 = (k - 1)*n
                    if (s%structured) then
                        call sys%solve_iteration(s%sd(i0 + 1:i0 + n), stat)
                        if (stat%code /= STATUS_OK) return
                    else
                        call la_small_lu_solve(s%wm, s%ipiv, s%sd(i0 + 1:i0 + n))
                    end if
                end do
                s%nsit = s%nsit + 1
                call sens_accumulate(s%nsn, s%sd, s%srewt, s%sacor, del)
            end if
            ! the rate of the iteration, as the state's (kept from step to step)
            if (m > 1) s%scrate = max(0.2_dp*s%scrate, del/delp)
            if (del*min(1.0_dp, 1.5_dp*s%scrate) <= tol) then
                conv = .true.
                exit
            end if
            if (m > 1 .and. del > 0.5_dp*delp) exit
            delp = del
            call sens_products(sys, n, s%ns, s%sacor, s%sjv, stat)
            if (stat%code /= STATUS_OK) return
            call sens_residual(s%nsn, hl0, s%sb, s%sjv, s%sacor, s%sd)
        end do
        if (.not. conv) call direct()
    contains
        !> A direct solve with I - h l0 J factored and inverted here.
        subroutine direct()
            call sens_matrix(s, sys, hl0, stat)
            if (stat%code /= STATUS_OK) return
            call inverse_times(n, s%ns, s%sinv, s%sb, s%sacor)
        end subroutine direct
    end subroutine sens_correct

    !> jv = J v at the system's last sens_point for the columns of v, n x ns (the
    !! sensitivities' vectors of n ns seen as their columns, without a copy).
    subroutine sens_products(sys, n, ns, v, jv, stat)
        class(ode_system_t), intent(inout) :: sys
        integer, intent(in) :: n, ns
        real(dp), intent(in) :: v(n, ns)
        real(dp), intent(out) :: jv(n, ns)
        type(status_t), intent(out) :: stat
        call sys%sens_jv(v, jv, stat)
    end subroutine sens_products

    !> z = jv + dfdp (the sensitivities' slope), vectors of m = n ns.
    pure subroutine sens_sum(m, jv, dfdp, z)
        integer, intent(in) :: m
        real(dp), intent(in) :: jv(m), dfdp(m)
        real(dp), intent(out) :: z(m)
        z = jv + dfdp
    end subroutine sens_sum

    !> The corrector's right-hand side b = h (J z + df/dp) - z2 (z2 the predicted scaled
    !! slope), vectors of m = n ns.
    pure subroutine sens_rhs(m, h, jv, dfdp, z2, b)
        integer, intent(in) :: m
        real(dp), intent(in) :: h, jv(m), dfdp(m), z2(m)
        real(dp), intent(out) :: b(m)
        b = h*(jv + dfdp) - z2
    end subroutine sens_rhs

    !> d = b + h l0 J a - a, the residual of (I - h l0 J) a = b.
    pure subroutine sens_residual(m, hl0, b, jv, a, d)
        integer, intent(in) :: m
        real(dp), intent(in) :: hl0, b(m), jv(m), a(m)
        real(dp), intent(out) :: d(m)
        d = b + hl0*jv - a
    end subroutine sens_residual

    !> a <- a + d and del = the weighted max-norm of d (rw the reciprocal weights).
    pure subroutine sens_accumulate(m, d, rw, a, del)
        integer, intent(in) :: m
        real(dp), intent(in) :: d(m), rw(m)
        real(dp), intent(inout) :: a(m)
        real(dp), intent(out) :: del
        integer :: i
        del = 0.0_dp
        do i = 1, m
            a(i) = a(i) + d(i)
            del = max(del, abs(d(i))*rw(i))
        end do
    end subroutine sens_accumulate

    !> One functional iteration a <- b + h l0 J a: d = b + h l0 jv - a, a <- a + d, and
    !! del = the weighted max-norm of d.
    pure subroutine sens_fixed_point(m, hl0, b, jv, rw, a, del)
        integer, intent(in) :: m
        real(dp), intent(in) :: hl0, b(m), jv(m), rw(m)
        real(dp), intent(inout) :: a(m)
        real(dp), intent(out) :: del
        real(dp) :: d
        integer :: i
        del = 0.0_dp
        do i = 1, m
            d = b(i) + hl0*jv(i) - a(i)
            a(i) = a(i) + d
            del = max(del, abs(d)*rw(i))
        end do
    end subroutine sens_fixed_point

    !> The sensitivities' own iteration matrix I - hl0 J at the point of the last
    !! sens_point (sjm) and its inverse (sinv, lapack_wrap's written-out Gauss-Jordan), with
    !! its h l0 and step (shl0, snslp).  The inverse solves every column with one product (a
    !! 10 x 10 LU solve a column cost about ten times that); the matrix is near I here (an
    !! Adams step, or one whose iteration failed to contract), so the inverse costs no
    !! accuracy worth the name, and the iteration's residuals use the exact J.
    subroutine sens_matrix(s, sys, hl0, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: hl0
        type(status_t), intent(inout) :: stat
        type(status_t) :: lst
        integer :: i
        call sys%sens_jacobian(s%sjm, stat)
        if (stat%code /= STATUS_OK) return
        s%sjm = -hl0*s%sjm
        do i = 1, s%n
            s%sjm(i, i) = s%sjm(i, i) + 1.0_dp
        end do
        s%nsdir = s%nsdir + 1
        s%shl0 = hl0
        s%snslp = s%nst
        s%shave = .true.
        call la_small_inverse(s%n, s%sjm, s%sinv, lst)
        if (lst%code /= STATUS_OK) then
            call set_error(stat, LSODA_ERR_SINGULAR, 'lsoda: the sensitivities'' iteration '// &
                'matrix I - h l0 J is singular')
        end if
    end subroutine sens_matrix

    !> w = p v for the columns of v (n x ns): the solves of sens_correct by the inverse.
    !! (The paper's model has n = 10: a column's sum then stays in registers.)
    pure subroutine inverse_times(n, ns, p, v, w)
        integer, intent(in) :: n, ns
        real(dp), intent(in) :: p(n, n), v(n, ns)
        real(dp), intent(out) :: w(n, ns)
        integer :: j, k
        if (n == 10) then
            call times10(ns, p, v, w)
            return
        end if
        do k = 1, ns
            w(:, k) = p(:, 1)*v(1, k)
            do j = 2, n
                w(:, k) = w(:, k) + p(:, j)*v(j, k)
            end do
        end do
    contains
        pure subroutine times10(m, a, x, y)
            integer, intent(in) :: m
            real(dp), intent(in) :: a(10, 10), x(10, m)
            real(dp), intent(out) :: y(10, m)
            real(dp) :: acc(10)
            integer :: jj, kk
            do kk = 1, m
                acc = a(:, 1)*x(1, kk)
                do jj = 2, 10
                    acc = acc + a(:, jj)*x(jj, kk)
                end do
                y(:, kk) = acc
            end do
        end subroutine times10
    end subroutine inverse_times

    !> k-th derivative at t of the polynomial held in a Nordsieck array yh of m rows (the
    !! state's, or the sensitivities' with dky their n x ns as one vector).
    subroutine interpolate(s, yh, m, t, k, dky, stat)
        type(lsoda_t), intent(in) :: s
        integer, intent(in) :: m
        real(dp), intent(in) :: yh(m, LMAX_ALL)
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(m)
        type(status_t), intent(out) :: stat
        real(dp) :: sc
        character(len=200) :: buf
        if (k < 0 .or. k > s%nq) then
            dky = 0.0_dp
            write (buf, '(a,i0,a,i0)') 'lsoda dense: derivative order k = ', k, &
                ' must be in 0..', s%nq
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        call s%check_in_step(t, 'dense', stat)
        if (stat%code /= STATUS_OK) then
            dky = yh(:, 1)
            return
        end if
        sc = 0.0_dp
        if (s%h /= 0.0_dp) sc = (t - s%t)/s%h
        call horner(yh, m, s%nq, s%h, sc, k, dky)
    end subroutine interpolate

    !> The k-th derivative of the polynomial of a Nordsieck array yh (order nq, step h) at
    !! the point sc h from the step's end.
    pure subroutine horner(yh, m, nq, h, sc, k, dky)
        integer, intent(in) :: m                        !! rows
        real(dp), intent(in) :: yh(m, LMAX_ALL)         !! Nordsieck array
        integer, intent(in) :: nq, k                    !! order, derivative
        real(dp), intent(in) :: h, sc                   !! step, (t - t_n)/h (t_n the step's end)
        real(dp), intent(out) :: dky(m)
        real(dp) :: c, t(2)
        integer :: i, j, jj, ic
        if (h == 0.0_dp) then
            dky = yh(:, 1)
            if (k > 0) dky = 0.0_dp
            return
        end if
        if (sc == 0.0_dp .and. k <= 1) then
            ! at the end of the step the Horner scheme below reduces to one column (the same
            ! numbers, without the sums of zero terms): y = yh(:,1), y' = yh(:,2)/h
            dky = yh(:, k + 1)
            if (k > 0) dky = dky*h**(-k)
            return
        end if
        if (k == 0) then
            ! the solution itself (every factor c below is 1, and 1 x = x exactly): two rows
            ! at a time, the sum in registers
            do i = 1, m - 1, 2
                t = yh(i:i + 1, nq + 1)
                do j = nq - 1, 0, -1
                    t = yh(i:i + 1, j + 1) + sc*t
                end do
                dky(i:i + 1) = t
            end do
            if (mod(m, 2) == 1) then
                t(1) = yh(m, nq + 1)
                do j = nq - 1, 0, -1
                    t(1) = yh(m, j + 1) + sc*t(1)
                end do
                dky(m) = t(1)
            end if
            return
        end if
        ! Horner scheme on the Nordsieck columns, differentiated k times
        ic = 1
        do jj = nq + 1 - k, nq
            ic = ic*jj
        end do
        c = real(ic, dp)
        dky = c*yh(:, nq + 1)
        do j = nq - 1, k, -1
            ic = 1
            do jj = j + 1 - k, j
                ic = ic*jj
            end do
            c = real(ic, dp)
            dky = c*yh(:, j + 1) + sc*dky
        end do
        if (k > 0) dky = dky*h**(-k)
    end subroutine horner

    ! ------------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------------

    !> Weighted max-norm max_i |v_i|*rw_i (rw = reciprocal weights).
    pure real(dp) function vmnorm(n, v, rw)
        integer, intent(in) :: n
        real(dp), intent(in) :: v(n)
        real(dp), intent(in) :: rw(n)
        integer :: i
        vmnorm = 0.0_dp
        do i = 1, n
            vmnorm = max(vmnorm, abs(v(i))*rw(i))
        end do
    end function vmnorm

    !> The weighted max-norm of a - b (vmnorm of the difference, without forming it).
    pure real(dp) function vmnorm_diff(n, a, b, rw)
        integer, intent(in) :: n
        real(dp), intent(in) :: a(n), b(n)
        real(dp), intent(in) :: rw(n)
        integer :: i
        vmnorm_diff = 0.0_dp
        do i = 1, n
            vmnorm_diff = max(vmnorm_diff, abs(a(i) - b(i))*rw(i))
        end do
    end function vmnorm_diff

    !> b = a (vectors of n).
    pure subroutine copy_vec(n, a, b)
        integer, intent(in) :: n
        real(dp), intent(in) :: a(n)
        real(dp), intent(out) :: b(n)
        b = a
    end subroutine copy_vec

    !> v <- r v (a vector of n).
    pure subroutine scale_vec(n, r, v)
        integer, intent(in) :: n
        real(dp), intent(in) :: r
        real(dp), intent(inout) :: v(n)
        v = v*r
    end subroutine scale_vec

    !> One functional (fixed-point) iteration of the Adams corrector, f on entry the
    !! right-hand side at y: f <- h f - yh2, del = ||f - acor|| (vmnorm), y = yh1 + l0 f,
    !! acor = f.
    pure subroutine functional_update(n, h, el1, yh1, yh2, rewt, f, acor, y, del)
        integer, intent(in) :: n
        real(dp), intent(in) :: h, el1                  !! step, l0
        real(dp), intent(in) :: yh1(n), yh2(n)          !! Nordsieck columns 1 and 2
        real(dp), intent(in) :: rewt(n)                 !! reciprocal weights
        real(dp), intent(inout) :: f(n), acor(n)
        real(dp), intent(out) :: y(n)
        real(dp), intent(out) :: del
        integer :: i
        del = 0.0_dp
        do i = 1, n
            f(i) = h*f(i) - yh2(i)
            del = max(del, abs(f(i) - acor(i))*rewt(i))
            y(i) = yh1(i) + el1*f(i)
            acor(i) = f(i)
        end do
    end subroutine functional_update

    !> The chord Newton iteration's residual r = h f - (yh2 + acor).
    pure subroutine newton_residual(n, h, f, yh2, acor, r)
        integer, intent(in) :: n
        real(dp), intent(in) :: h, f(n), yh2(n), acor(n)
        real(dp), intent(out) :: r(n)
        r = h*f - (yh2 + acor)
    end subroutine newton_residual

    !> The chord Newton iteration's update, y the correction on entry: del = ||y|| (vmnorm),
    !! acor <- acor + y, y = yh1 + l0 acor.
    pure subroutine newton_update(n, el1, yh1, rewt, acor, y, del)
        integer, intent(in) :: n
        real(dp), intent(in) :: el1, yh1(n), rewt(n)
        real(dp), intent(inout) :: acor(n), y(n)
        real(dp), intent(out) :: del
        integer :: i
        del = 0.0_dp
        do i = 1, n
            del = max(del, abs(y(i))*rewt(i))
            acor(i) = acor(i) + y(i)
            y(i) = yh1(i) + el1*acor(i)
        end do
    end subroutine newton_update

    subroutine realloc_vec(v, n)
        real(dp), allocatable, intent(inout) :: v(:)
        integer, intent(in) :: n
        if (allocated(v)) then
            if (size(v) == n) return
            deallocate (v)
        end if
        allocate (v(n))
    end subroutine realloc_vec

    !> Nordsieck coefficients l_j and error-test constants of the Adams (method 1, orders
    !! 1..12) and BDF (method 2, orders 1..5) formulas.
    !!
    !! Adams order q: with P(x) = prod_{i=1}^{q-1} (x+i), l_1 = int_{-1}^0 P/(q-1)!,
    !! l_{i+1} = [x^{i-1}]P / (i (q-1)!), i = 1..q; error constant from int_{-1}^0 x P.
    !! BDF order q: with P(x) = prod_{i=1}^{q} (x+i), l_i = [x^{i-1}]P / [x^1]P.
    !! tesco(1,q), tesco(2,q), tesco(3,q): divisors turning the Nordsieck differences into
    !! error estimates at orders q-1, q, q+1.  cm1/cm2: l_{q+1}*tesco(2,q) for the
    !! method-switching estimates.
    pure subroutine set_coefficients(elco, tesco, cm1, cm2)
        real(dp), intent(out) :: elco(:, :, :)
        real(dp), intent(out) :: tesco(:, :, :)
        real(dp), intent(out) :: cm1(:), cm2(:)
        real(dp) :: pc(LMAX_ALL + 1), pint, xpin, rqfac, rq1fac, sgn, ragq
        integer :: q, i

        elco = 0.0_dp
        tesco = 0.0_dp
        ! Adams-Moulton (rqfac = 1/q!, rq1fac = 1/(q-1)!, built by successive division)
        rqfac = 1.0_dp
        pc = 0.0_dp
        pc(1) = 1.0_dp                       ! P for q = 1
        do q = 1, MAXORD_ADAMS
            rq1fac = rqfac
            rqfac = rqfac/q
            if (q > 1) call poly_times_linear(pc, q - 2, real(q - 1, dp))   ! P *= (x + q - 1)
            pint = 0.0_dp
            xpin = 0.0_dp
            sgn = 1.0_dp
            do i = 1, q
                pint = pint + sgn*pc(i)/i
                xpin = xpin + sgn*pc(i)/(i + 1)
                sgn = -sgn
            end do
            elco(1, q, 1) = pint*rq1fac
            elco(2, q, 1) = 1.0_dp
            do i = 2, q
                elco(i + 1, q, 1) = rq1fac*pc(i)/i
            end do
            ragq = 1.0_dp/(rqfac*xpin)
            tesco(2, q, 1) = ragq
            if (q < MAXORD_ADAMS) tesco(1, q + 1, 1) = ragq*rqfac/(q + 1)
        end do
        do q = 2, MAXORD_ADAMS
            tesco(3, q - 1, 1) = tesco(2, q, 1)
        end do
        tesco(1, 1, 1) = 0.0_dp
        tesco(3, MAXORD_ADAMS, 1) = 0.0_dp
        ! BDF
        pc = 0.0_dp
        pc(1) = 1.0_dp
        rq1fac = 1.0_dp                       ! 1/(q-1)!
        do q = 1, MAXORD_BDF
            call poly_times_linear(pc, q - 1, real(q, dp))   ! P *= (x + q)
            do i = 1, q + 1
                elco(i, q, 2) = pc(i)/pc(2)
            end do
            elco(2, q, 2) = 1.0_dp
            tesco(1, q, 2) = rq1fac
            tesco(2, q, 2) = (q + 1)/elco(1, q, 2)
            tesco(3, q, 2) = (q + 2)/elco(1, q, 2)
            rq1fac = rq1fac/q
        end do
        do q = 1, MAXORD_ADAMS
            cm1(q) = tesco(2, q, 1)*elco(q + 1, q, 1)
        end do
        do q = 1, MAXORD_BDF
            cm2(q) = tesco(2, q, 2)*elco(q + 1, q, 2)
        end do
    end subroutine set_coefficients

    !> pc (degree deg, coefficients pc(1..deg+1), pc(1) constant) times (x + a).
    pure subroutine poly_times_linear(pc, deg, a)
        real(dp), intent(inout) :: pc(:)
        integer, intent(in) :: deg
        real(dp), intent(in) :: a
        integer :: i
        pc(deg + 2) = pc(deg + 1)
        do i = deg + 1, 2, -1
            pc(i) = pc(i - 1) + a*pc(i)
        end do
        pc(1) = a*pc(1)
    end subroutine poly_times_linear

end module lsoda
