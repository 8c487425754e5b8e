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
!! All state lives in a `lsoda_t` object, so independent integrations can be interleaved.
!! No routine stops the program: every failure is returned in a status_t with one of the
!! LSODA_ERR_* codes (or the code the right-hand side returned) and a message naming the
!! cause and the time reached; the solution up to the failure is kept.
module lsoda
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, LSODA_ERR_MAX_STEPS, &
        LSODA_ERR_TOO_MUCH_ACCURACY, LSODA_ERR_ERROR_TEST, LSODA_ERR_CONVERGENCE, &
        LSODA_ERR_ILLEGAL_INPUT, LSODA_ERR_SINGULAR
    use ode_system, only: ode_system_t, integrator_t, integrator_stats_t, sens_init_args, &
        METHOD_ADAMS, METHOD_BDF
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
    integer, parameter :: DEFAULT_MAX_STEPS = 500000
    integer, parameter :: SENS_MAXIT = 4           !! sensitivity corrector iterations
    real(dp), parameter :: SENS_CONV = 0.5_dp      !! their test: this part of the state's
    real(dp), parameter :: SENS_CONV_EC = 0.1_dp   !! the same in the error control (Adams)

    ! internal outcome of one call of take_step
    integer, parameter :: KF_OK = 0, KF_ERRTEST = -1, KF_CONV = -2, KF_SINGULAR = -3, &
        KF_FATAL = -4


    !> One integration: the Nordsieck array, method state, work arrays and counters.
    type, extends(integrator_t), public :: lsoda_t
        private
        ! options of the next init (set_options)
        integer :: opt_order_adams = MAXORD_ADAMS, opt_order_bdf = MAXORD_BDF
        logical :: opt_start_bdf = .false., opt_adams_only = .false.
        logical :: ready = .false.      ! init succeeded
        logical :: started = .false.    ! initial step size chosen
        integer :: n = 0
        real(dp) :: rtol = 0.0_dp
        real(dp), allocatable :: atol(:)
        real(dp), allocatable :: yh(:, :)      ! Nordsieck array: yh(:,j+1) = h**j y^(j)/j!
        real(dp), allocatable :: rewt(:)       ! reciprocal error weights 1/(rtol|y|+atol)
        real(dp), allocatable :: y(:), savf(:), acor(:), ftem(:)
        real(dp), allocatable :: wm(:, :)      ! iteration matrix / its LU factors
        integer, allocatable :: ipiv(:)
        real(dp) :: elco(LMAX_ALL, MAXORD_ADAMS, 2) = 0.0_dp
        real(dp) :: tesco(3, MAXORD_ADAMS, 2) = 0.0_dp
        real(dp) :: cm1(MAXORD_ADAMS) = 0.0_dp, cm2(MAXORD_BDF) = 0.0_dp
        real(dp) :: el(LMAX_ALL) = 0.0_dp
        real(dp) :: tn = 0.0_dp, told = 0.0_dp, tlast = 0.0_dp, dir = 1.0_dp
        real(dp) :: h = 0.0_dp, hold = 0.0_dp, hu = 0.0_dp, h0_user = 0.0_dp
        real(dp) :: hmin = 0.0_dp, hmxi = 0.0_dp
        real(dp) :: tcrit = 0.0_dp
        logical :: have_tcrit = .false.
        real(dp) :: rc = 0.0_dp, el0 = 1.0_dp, crate = 0.7_dp, conit = 0.0_dp, rmax = 1.0e4_dp
        real(dp) :: pdest = 0.0_dp, pdlast = 0.0_dp, pdnorm = 0.0_dp, tsw = 0.0_dp
        integer :: nq = 1, l = 2, lmax = 13, meth = METHOD_ADAMS, mused = 0, nqu = 0
        integer :: meth0 = METHOD_ADAMS        ! method of the first step
        logical :: adams_only = .false.        ! never switch to BDF
        logical :: structured = .false.        ! the system solves with P (has_iteration_solver)
        integer :: ialth = 2, icount = SWITCH_WAIT, irflag = 0, nslp = 0, jstart = 0
        integer :: kflag = 0
        logical :: ipup = .false., jcur = .false.
        integer :: mxordn = MAXORD_ADAMS, mxords = MAXORD_BDF
        integer :: max_steps = DEFAULT_MAX_STEPS
        integer :: nst = 0, nfe = 0, nje = 0, nlu = 0, nswitch = 0, steps_call = 0
        integer :: ncfn = 0, netf = 0
        ! forward sensitivities (sens_init): ns columns of n, one vector of n ns
        integer :: ns = 0, nsn = 0
        logical :: sens_errcon = .false.       ! in the error test
        real(dp), allocatable :: zh(:, :)      ! their Nordsieck array (nsn, LMAX_ALL)
        real(dp), allocatable :: satol(:), srewt(:), sacor(:)
        real(dp), allocatable :: sdfdp(:, :)   ! df/dp at the step's point (n, ns)
        ! sens_correct's work vectors of n ns (the n x ns columns one after another, as zh's):
        ! right-hand side b, change d, products J v
        real(dp), allocatable :: sb(:), sd(:), sjv(:)
        real(dp), allocatable :: sjm(:, :)     ! the sensitivities' own matrix I - h l0 J
        real(dp), allocatable :: sinv(:, :)    ! its inverse (the solves of all columns at once)
        real(dp) :: shl0 = 0.0_dp              ! its h l0
        integer :: snslp = 0                   ! the step it was formed at
        logical :: shave = .false.             ! it is formed
        integer :: nsp = 0, nsit = 0, nsdir = 0
        real(dp) :: scrate = 0.7_dp            ! their iteration's convergence rate
    contains
        procedure :: init => lsoda_init
        procedure :: integrate => lsoda_integrate
        procedure :: step => lsoda_step
        procedure :: dense => lsoda_dense
        procedure :: stats => lsoda_get_stats
        procedure :: set_tcrit => lsoda_set_tcrit
        procedure :: name => lsoda_name
        procedure :: set_options => lsoda_set_options
        procedure :: sens_init => lsoda_sens_init
        procedure :: sens_dense => lsoda_sens_dense
        procedure :: sens_dense_dot => lsoda_sens_dense_dot
    end type lsoda_t

contains

    ! ------------------------------------------------------------------------------------
    ! Public routines
    ! ------------------------------------------------------------------------------------

    !> Start an integration at (t0, y0).
    !!
    !! sys       [in,out] the right-hand side; called once here for f(t0, y0).
    !! t0        [in]  initial time (units of the problem's independent variable).
    !! y0        [in]  initial state, size n >= 1.
    !! rtol      [in]  relative tolerance, >= 0.
    !! atol      [in]  absolute tolerance, size 1 (same for all components) or n, each >= 0.
    !!                 Error weights w_i = rtol*|y_i| + atol_i must stay > 0.
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

        s%ready = .false.
        s%started = .false.
        n = size(y0)
        if (n < 1) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda init: empty state vector')
            return
        end if
        if (.not. (rtol >= 0.0_dp)) then
            write (buf, '(a,es11.3e3,a)') 'lsoda init: rtol = ', rtol, ' is negative'
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        if (size(atol) /= 1 .and. size(atol) /= n) then
            write (buf, '(a,i0,a,i0)') 'lsoda init: size(atol) = ', size(atol), &
                ' must be 1 or n = ', n
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        if (.not. all(atol >= 0.0_dp)) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda init: atol has a negative entry')
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
        s%hmxi = 0.0_dp
        if (present(hmax)) then
            if (.not. (hmax > 0.0_dp)) then
                call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda init: hmax must be > 0')
                return
            end if
            s%hmxi = 1.0_dp/hmax
        end if
        s%max_steps = DEFAULT_MAX_STEPS
        if (present(max_steps)) then
            if (max_steps < 1) then
                call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda init: max_steps must be >= 1')
                return
            end if
            s%max_steps = max_steps
        end if
        s%h0_user = 0.0_dp
        if (present(h0)) s%h0_user = abs(h0)
        s%have_tcrit = present(tcrit)
        if (present(tcrit)) s%tcrit = tcrit

        s%n = n
        s%rtol = rtol
        call realloc_vec(s%atol, n)
        if (size(atol) == 1) then
            s%atol = atol(1)
        else
            s%atol = atol
        end if
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

        s%tn = t0
        s%told = t0
        s%tlast = t0
        s%dir = 1.0_dp
        s%h = 0.0_dp
        s%hold = 0.0_dp
        s%hu = 0.0_dp
        s%hmin = 0.0_dp
        s%nq = 1
        s%l = 2
        s%meth0 = merge(METHOD_BDF, METHOD_ADAMS, s%opt_start_bdf)
        s%adams_only = s%opt_adams_only
        if (s%adams_only .and. s%meth0 == METHOD_BDF) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda init: start_bdf and '// &
                'nonstiff_only exclude each other')
            return
        end if
        s%meth = s%meth0
        s%mused = 0
        s%nqu = 0
        s%jstart = 0
        s%kflag = 0
        s%nst = 0
        s%nfe = 0
        s%nje = 0
        s%nlu = 0
        s%ncfn = 0
        s%netf = 0
        s%nswitch = 0
        s%steps_call = 0
        s%tsw = t0
        s%pdnorm = 0.0_dp
        s%ns = 0
        s%nsn = 0
        s%nsp = 0
        s%nsit = 0
        s%nsdir = 0

        s%yh(:, 1) = y0
        s%y = y0
        call sys%rhs(t0, s%y, s%savf, stat)
        s%nfe = 1
        if (stat%code /= STATUS_OK) then
            call prefix_time(stat, t0)
            return
        end if
        s%yh(:, 2) = s%savf     ! f(t0,y0); scaled by h0 when the first step size is known
        s%ready = .true.
    end subroutine lsoda_init

    !> Advance the solution to tout and return y(tout).
    !!
    !! Steps past tout (never past tcrit) and interpolates back.  tout may lie anywhere
    !! ahead of the last output time in the direction of integration (the direction is
    !! fixed by the first call).
    !!
    !! sys  [in,out] the right-hand side.
    !! tout [in]  output time.
    !! y    [out] size n: the solution at tout; on failure the solution at the time reached
    !!            (stats()%t_current).
    !! stat [out] STATUS_OK; LSODA_ERR_MAX_STEPS (max_steps steps in this call),
    !!            LSODA_ERR_TOO_MUCH_ACCURACY, LSODA_ERR_ERROR_TEST, LSODA_ERR_CONVERGENCE,
    !!            LSODA_ERR_SINGULAR, LSODA_ERR_ILLEGAL_INPUT (no init, size(y) /= n, tout
    !!            behind the last output, tcrit behind tout), or the right-hand side's own
    !!            code with its message prefixed by the time reached.
    subroutine lsoda_integrate(s, sys, tout, y, stat)
        class(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: tout
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        type(status_t) :: dst
        character(len=160) :: buf

        if (.not. s%ready) then
            y = 0.0_dp
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda integrate: solver not initialised')
            return
        end if
        if (size(y) /= s%n) then
            y = 0.0_dp
            write (buf, '(a,i0,a,i0)') 'lsoda integrate: size(y) = ', size(y), ' but n = ', s%n
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        y = s%yh(:, 1)
        if (.not. s%started) then
            if (tout == s%tn) then
                s%tlast = tout
                return
            end if
            s%dir = sign(1.0_dp, tout - s%tn)
        else if ((tout - s%tlast)*s%dir < 0.0_dp) then
            write (buf, '(a,es13.5e3,a,es13.5e3,a)') 'lsoda integrate: tout = ', tout, &
                ' is behind the last output time ', s%tlast, ' in the direction of integration'
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        if (s%have_tcrit) then
            if ((s%tcrit - tout)*s%dir < 0.0_dp) then
                write (buf, '(a,es13.5e3,a,es13.5e3)') 'lsoda integrate: tcrit = ', s%tcrit, &
                    ' is behind tout = ', tout
                call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
                return
            end if
        end if
        if (.not. s%started) then
            call start_integration(s, tout, .true., stat)
            if (stat%code /= STATUS_OK) return
        end if

        s%steps_call = 0
        do
            if ((s%tn - tout)*s%dir >= 0.0_dp) then
                call interpolate(s, s%yh, s%n, tout, 0, y, dst)
                if (dst%code /= STATUS_OK) then
                    stat = dst
                    y = s%yh(:, 1)
                    return
                end if
                s%tlast = tout
                return
            end if
            if (s%have_tcrit) then
                if (at_tcrit(s)) then
                    y = s%yh(:, 1)
                    s%tlast = tout
                    return
                end if
            end if
            call one_step(s, sys, stat)
            if (stat%code /= STATUS_OK) then
                y = s%yh(:, 1)
                return
            end if
        end do
    end subroutine lsoda_integrate

    !> Take exactly one internal step (never past tcrit).  After it, dense() gives the
    !! solution anywhere in [t_current - h_last, t_current].
    !!
    !! sys  [in,out] the right-hand side.
    !! stat [out] as for integrate; LSODA_ERR_ILLEGAL_INPUT also when the integration
    !!            already stands at tcrit.
    !! tout [in, optional] only used before the first step: a time the caller wants to
    !!            reach (fixes the direction and scales the first step size); without it
    !!            the direction is towards tcrit if set, else forward.
    subroutine lsoda_step(s, sys, stat, tout)
        class(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: tout
        real(dp) :: th
        logical :: have

        if (.not. s%ready) then
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda step: solver not initialised')
            return
        end if
        if (.not. s%started) then
            have = .false.
            th = s%tn
            if (present(tout)) then
                if (tout /= s%tn) then
                    have = .true.
                    th = tout
                end if
            end if
            if (.not. have .and. s%have_tcrit) then
                if (s%tcrit /= s%tn) then
                    have = .true.
                    th = s%tcrit
                end if
            end if
            if (have) s%dir = sign(1.0_dp, th - s%tn)
            if (s%have_tcrit) then
                if ((s%tcrit - s%tn)*s%dir <= 0.0_dp) then
                    call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, &
                        'lsoda step: the integration already stands at tcrit')
                    return
                end if
            end if
            call start_integration(s, th, have, stat)
            if (stat%code /= STATUS_OK) return
        else if (s%have_tcrit) then
            if (at_tcrit(s)) then
                call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, &
                    'lsoda step: the integration already stands at tcrit')
                return
            end if
        end if
        s%steps_call = 0
        call one_step(s, sys, stat)
    end subroutine lsoda_step

    !> k-th derivative of the interpolating polynomial at t, within the last step.
    !!
    !! t    [in]  time in [t_current - h_last, t_current] (roundoff tolerated).
    !! k    [in]  derivative order, 0 <= k <= current order (order_next).
    !! dky  [out] size n: d^k y / dt^k at t (units of y per time**k).
    !! stat [out] STATUS_OK or LSODA_ERR_ILLEGAL_INPUT (t outside the step, bad k or size).
    subroutine lsoda_dense(s, t, k, dky, stat)
        class(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(:)
        type(status_t), intent(out) :: stat
        if (.not. s%ready .or. size(dky) /= s%n) then
            dky = 0.0_dp
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, &
                'lsoda dense: solver not initialised or size(dky) /= n')
            return
        end if
        call interpolate(s, s%yh, s%n, t, k, dky, stat)
    end subroutine lsoda_dense

    !> Counters and method state (see integrator_stats_t).
    function lsoda_get_stats(s) result(st)
        class(lsoda_t), intent(in) :: s
        type(integrator_stats_t) :: st
        st%steps = s%nst
        st%rhs_evals = s%nfe
        st%jac_evals = s%nje
        st%lu_decomps = s%nlu
        st%conv_failures = s%ncfn
        st%error_test_failures = s%netf
        st%method_switches = s%nswitch
        st%method_last = s%mused
        st%order_last = s%nqu
        st%method_next = s%meth
        st%order_next = s%nq
        st%h_last = s%hu
        st%h_next = s%h
        st%t_current = s%tn
        st%sens_points = s%nsp
        st%sens_iterations = s%nsit
        st%sens_direct = s%nsdir
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

    !> The integrator's name in output files.
    pure function lsoda_name(s) result(nm)
        class(lsoda_t), intent(in) :: s
        character(len=:), allocatable :: nm
        call unused(s)
        nm = 'lsoda'
    end function lsoda_name

    !> Set (tcrit present) or remove (absent) the hard stop time.
    !!
    !! tcrit [in, optional] new stop time; it must not lie behind the time already reached
    !!       (then stat = LSODA_ERR_ILLEGAL_INPUT and the old setting stays).
    !! stat  [out, optional] STATUS_OK or LSODA_ERR_ILLEGAL_INPUT.
    subroutine lsoda_set_tcrit(s, tcrit, stat)
        class(lsoda_t), intent(inout) :: s
        real(dp), intent(in), optional :: tcrit
        type(status_t), intent(out), optional :: stat
        character(len=120) :: buf
        if (present(stat)) stat%code = STATUS_OK
        if (.not. present(tcrit)) then
            s%have_tcrit = .false.
            return
        end if
        if (s%started .and. (tcrit - s%tn)*s%dir < 0.0_dp) then
            if (present(stat)) then
                write (buf, '(a,es13.5e3,a,es13.5e3)') 'lsoda set_tcrit: tcrit = ', tcrit, &
                    ' is behind the time reached ', s%tn
                call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            end if
            return
        end if
        s%tcrit = tcrit
        s%have_tcrit = .true.
    end subroutine lsoda_set_tcrit

    !> Start forward sensitivities (see the module header): after init, before the first
    !! step.
    !!
    !! sys   [in,out] the right-hand side; its sens_point and sens_jv give the terms.
    !! s0    [in]  (n, ns) the sensitivities at t0, ns >= 1.
    !! stat  [out] STATUS_OK; LSODA_ERR_ILLEGAL_INPUT (no init, the integration has
    !!             started, a bad shape or scale); or the system's code from its terms.
    !! scale [in, optional] (ns) the size of sensitivity k against the state's: its absolute
    !!             tolerance is atol scale(k) (default 1), > 0.
    !! error_control [in, optional] .true.: the sensitivities take part in the error test
    !!             and the order selection (default .false.: the state's steps alone).
    subroutine lsoda_sens_init(s, sys, s0, stat, scale, error_control)
        class(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: s0(:, :)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: scale(:)
        logical, intent(in), optional :: error_control
        real(dp) :: sc(size(s0, 2)), w
        integer :: ns, n, k, i
        stat%code = STATUS_OK
        s%ns = 0
        s%nsn = 0
        n = s%n
        ns = size(s0, 2)
        call sens_init_args('lsoda sens_init', LSODA_ERR_ILLEGAL_INPUT, s%ready, &
                            s%started, n, s0, sc, stat, scale)
        if (stat%code /= STATUS_OK) return
        s%sens_errcon = .false.
        if (present(error_control)) s%sens_errcon = error_control
        s%nsn = n*ns
        if (allocated(s%zh)) then
            if (size(s%zh, 1) /= s%nsn) deallocate (s%zh)
        end if
        if (.not. allocated(s%zh)) allocate (s%zh(s%nsn, LMAX_ALL))
        call realloc_vec(s%satol, s%nsn)
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
        do k = 1, ns
            do i = 1, n
                ! atol = 0 (a relative test only) would make a weight infinite where s = 0
                w = s%atol(i)
                if (.not. (w > 0.0_dp)) w = max(s%rtol, UROUND)
                s%satol(i + (k - 1)*n) = w*sc(k)
            end do
        end do
        s%zh(:, 1) = reshape(s0, [s%nsn])
        s%ns = ns
        ! the slope at t0 (scaled by the first step in start_integration)
        call sens_slope(s, sys, s%tn, s%yh(:, 1), stat)
        if (stat%code /= STATUS_OK) then
            call prefix_time(stat, s%tn)
            s%ns = 0
            s%nsn = 0
        end if
    end subroutine lsoda_sens_init

    !> The sensitivities (k = 0) or their k-th derivative at t within the last step (as
    !! dense for the state).
    !!
    !! ds   [out] (n, ns).
    !! stat [out] STATUS_OK or LSODA_ERR_ILLEGAL_INPUT (no sensitivities, t outside the
    !!            step, a bad k or shape).
    subroutine lsoda_sens_dense(s, t, k, ds, stat)
        class(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: ds(:, :)
        type(status_t), intent(out) :: stat
        if (.not. s%ready .or. s%ns == 0 .or. size(ds, 1) /= s%n .or. size(ds, 2) /= s%ns) then
            ds = 0.0_dp
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, 'lsoda sens_dense: no '// &
                'sensitivities, or ds is not n x ns')
            return
        end if
        call interpolate(s, s%zh, s%nsn, t, k, ds, stat)     ! ds as a vector of n ns
    end subroutine lsoda_sens_dense

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
        call check_in_step(s, t, 'lsoda sens_dense_dot', stat)
        if (stat%code /= STATUS_OK) return
        nnz = 0
        do i = 1, s%n
            if (g(i) /= 0.0_dp) then
                nnz = nnz + 1
                nz(nnz) = i
            end if
        end do
        sc = 0.0_dp
        if (s%h /= 0.0_dp) sc = (t - s%tn)/s%h
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

    ! ------------------------------------------------------------------------------------
    ! Driver level
    ! ------------------------------------------------------------------------------------

    !> Choose the first step size (LSODE/LSODA rule) and scale yh(:,2) = h0*f0.
    subroutine start_integration(s, tout, have_tout, stat)
        type(lsoda_t), intent(inout) :: s
        real(dp), intent(in) :: tout
        logical, intent(in) :: have_tout
        type(status_t), intent(out) :: stat
        real(dp) :: tdist, w0, tol, sm, h0, rh
        integer :: i
        character(len=160) :: buf

        call update_weights(s, stat)
        if (stat%code /= STATUS_OK) return
        if (UROUND*vmnorm(s%n, s%yh(:, 1), s%rewt) > 0.01_dp) then
            call too_much_accuracy(s, stat)
            return
        end if
        if (s%h0_user > 0.0_dp) then
            h0 = s%h0_user
        else
            if (have_tout) then
                tdist = abs(tout - s%tn)
                w0 = max(abs(s%tn), abs(tout))
                if (tdist < 2.0_dp*UROUND*w0) then
                    write (buf, '(a,es13.5e3,a)') 'lsoda: tout is too close to t0 = ', s%tn, &
                        ' to start the integration'
                    call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
                    return
                end if
            else
                tdist = huge(1.0_dp)
                w0 = max(abs(s%tn), 1.0_dp)
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
            if ((s%tn + h0 - s%tcrit)*h0 > 0.0_dp) h0 = (s%tcrit - s%tn)*(1.0_dp - 4.0_dp*UROUND)
        end if
        s%h = h0
        s%yh(:, 2) = h0*s%yh(:, 2)
        if (s%ns > 0) s%zh(:, 2) = h0*s%zh(:, 2)
        s%jstart = 0
        s%started = .true.
    end subroutine start_integration

    !> True when tn is at tcrit up to roundoff.
    logical function at_tcrit(s)
        type(lsoda_t), intent(in) :: s
        at_tcrit = abs(s%tn - s%tcrit) <= 100.0_dp*UROUND*(abs(s%tn) + abs(s%h))
    end function at_tcrit

    !> Checks before a step, the step itself, and the bookkeeping after it.
    subroutine one_step(s, sys, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(inout) :: stat
        real(dp) :: tnext
        character(len=200) :: buf

        if (s%steps_call >= s%max_steps) then
            write (buf, '(a,i0,a,es15.7e3)') 'lsoda: ', s%max_steps, &
                ' steps taken in this call without reaching tout; t reached = ', s%tn
            call set_error(stat, LSODA_ERR_MAX_STEPS, trim(buf))
            return
        end if
        if (s%nst > 0) then
            call update_weights(s, stat)
            if (stat%code /= STATUS_OK) return
            if (UROUND*vmnorm(s%n, s%yh(:, 1), s%rewt) > 0.01_dp) then
                call too_much_accuracy(s, stat)
                return
            end if
        end if
        if (s%have_tcrit .and. s%jstart /= 0) then
            tnext = s%tn + s%h*(1.0_dp + 4.0_dp*UROUND)
            if ((tnext - s%tcrit)*s%h > 0.0_dp) then
                s%h = (s%tcrit - s%tn)*(1.0_dp - 4.0_dp*UROUND)
                if (s%jstart > 0) s%jstart = -2
            end if
        end if

        call take_step(s, sys, stat)

        select case (s%kflag)
        case (KF_OK)
            s%steps_call = s%steps_call + 1
            if (s%meth /= s%mused) then
                s%tsw = s%tn
                s%nswitch = s%nswitch + 1
                s%jstart = -1
            end if
            ! A step cut short to end at tcrit lands there only up to roundoff (it is cut
            ! to (tcrit - tn)*(1 - 4 u) so as never to pass it): it has reached tcrit, and
            ! says so, or a caller stepping until t_current >= tcrit would ask for a step
            ! that no longer fits (a body at rest takes one step straight to tcrit).
            if (s%have_tcrit) then
                if (at_tcrit(s)) s%tn = s%tcrit
            end if
        case (KF_ERRTEST)
            write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: error test failed repeatedly at t = ', &
                s%tn, ' with |h| = ', abs(s%h)
            call set_error(stat, LSODA_ERR_ERROR_TEST, trim(buf)//' (discontinuity or '// &
                'singularity of f?)')
        case (KF_CONV)
            write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: corrector failed to converge '// &
                'repeatedly at t = ', s%tn, ' with |h| = ', abs(s%h)
            call set_error(stat, LSODA_ERR_CONVERGENCE, trim(buf))
        case (KF_SINGULAR)
            write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: iteration matrix I - h*l0*J '// &
                'singular repeatedly at t = ', s%tn, ' with |h| = ', abs(s%h)
            call set_error(stat, LSODA_ERR_SINGULAR, trim(buf))
        case default
            ! KF_FATAL: stat already set (rhs/jacobian failure, prefixed with the time)
            continue
        end select
    end subroutine one_step

    !> Error weights from the current solution: rewt = 1/(rtol*|y| + atol).
    subroutine update_weights(s, stat)
        type(lsoda_t), intent(inout) :: s
        type(status_t), intent(inout) :: stat
        integer :: i
        character(len=160) :: buf
        call weights(s%n, s%rtol, s%yh(:, 1), s%atol, s%rewt, i)
        if (i > 0) then
            write (buf, '(a,i0,a,es15.7e3,a)') 'lsoda: error weight of component ', i, &
                ' became zero at t = ', s%tn, ' (atol(i) = 0 and y(i) = 0)'
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        if (s%ns > 0) call sens_weights(s%nsn, s%rtol, s%zh(:, 1), s%satol, s%srewt)
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

    subroutine too_much_accuracy(s, stat)
        type(lsoda_t), intent(in) :: s
        type(status_t), intent(inout) :: stat
        character(len=200) :: buf
        write (buf, '(a,es15.7e3,a,es11.3e3)') 'lsoda: too much accuracy requested for the '// &
            'machine precision at t = ', s%tn, '; scale the tolerances up by at least ', &
            200.0_dp*UROUND*vmnorm(s%n, s%yh(:, 1), s%rewt)
        call set_error(stat, LSODA_ERR_TOO_MUCH_ACCURACY, trim(buf))
    end subroutine too_much_accuracy

    ! ------------------------------------------------------------------------------------
    ! The step (one successful step, with retries)
    ! ------------------------------------------------------------------------------------

    !> One step of the current method, retrying with smaller h / other order after
    !! error-test or convergence failures, choosing order, step and method for the next
    !! step on success.  Sets s%kflag (KF_*).  On failure tn and yh are as before the call.
    subroutine take_step(s, sys, stat)
        type(lsoda_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(inout) :: stat
        integer :: ncf, m, newq, nqm, lm
        logical :: newton, converged, singular, fatal, switched
        real(dp) :: del, delp, dsm, rate, rm, dcon, pnorm, rh, rh1, rh2, rh1it, pdh, exsm
        real(dp) :: dm, exm, alpha

        s%kflag = KF_OK
        s%told = s%tn
        ncf = 0
        s%jcur = .false.
        del = 0.0_dp
        delp = 0.0_dp
        dsm = 0.0_dp
        rh = 1.0_dp
        rh2 = 1.0_dp
        nqm = 1

        select case (s%jstart)
        case (0)
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
        case (-1)
            ! method switched on the previous step
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
        case (-2)
            ! h changed by the driver (tcrit)
            if (s%h /= s%hold) then
                rh = s%h/s%hold
                s%h = s%hold
                call rescale(s, rh, .false.)
            end if
        case default
            continue
        end select

        attempt: do
            newton = s%meth == METHOD_BDF
            if (abs(s%rc - 1.0_dp) > CCMAX) s%ipup = newton
            if (s%nst >= s%nslp + MSBP) s%ipup = newton
            s%tn = s%tn + s%h
            call predict(s)
            pnorm = vmnorm(s%n, s%yh(:, 1), s%rewt)

            singular = .false.
            fatal = .false.
            converged = .false.
            corrector: do
                m = 0
                rate = 0.0_dp
                del = 0.0_dp
                call copy_vec(s%n, s%yh(:, 1), s%y)
                call sys%rhs(s%tn, s%y, s%savf, stat)
                s%nfe = s%nfe + 1
                if (stat%code /= STATUS_OK) then
                    call fail_fatal(s, stat)
                    return
                end if
                if (s%ipup) then
                    call build_iteration_matrix(s, sys, stat, singular)
                    if (stat%code /= STATUS_OK) then
                        call fail_fatal(s, stat)
                        return
                    end if
                    s%ipup = .false.
                    s%rc = 1.0_dp
                    s%nslp = s%nst
                    s%crate = 0.7_dp
                    if (singular) exit corrector
                end if
                s%acor = 0.0_dp
                iterate: do
                    if (.not. newton) then
                        call functional_update(s%n, s%h, s%el(1), s%yh(:, 1), s%yh(:, 2), &
                                               s%rewt, s%savf, s%acor, s%y, del)
                    else
                        ! chord Newton iteration
                        call newton_residual(s%n, s%h, s%savf, s%yh(:, 2), s%acor, s%y)
                        if (s%structured) then
                            call sys%solve_iteration(s%y, stat)
                        else
                            call la_lu_solve(s%wm, s%ipiv, s%y, stat)
                        end if
                        if (stat%code /= STATUS_OK) then
                            fatal = .true.     ! cannot happen with consistent shapes
                            exit corrector
                        end if
                        call newton_update(s%n, s%el(1), s%yh(:, 1), s%rewt, s%acor, s%y, del)
                    end if
                    ! convergence test; at least two iterations for Adams (Lipschitz estimate)
                    if (del <= 100.0_dp*pnorm*UROUND) then
                        converged = .true.
                        exit corrector
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
                            converged = .true.
                            exit corrector
                        end if
                    end if
                    m = m + 1
                    if (m == MAXCOR) exit iterate
                    if (m >= 2 .and. del > 2.0_dp*delp) exit iterate
                    delp = del
                    call sys%rhs(s%tn, s%y, s%savf, stat)
                    s%nfe = s%nfe + 1
                    if (stat%code /= STATUS_OK) then
                        call fail_fatal(s, stat)
                        return
                    end if
                end do iterate
                ! the iteration failed: retry once with a fresh matrix if it was old
                if (.not. newton .or. s%jcur) exit corrector
                s%ipup = .true.
            end do corrector

            if (.not. converged) then
                ! convergence failure (or singular matrix)
                ncf = ncf + 1
                s%ncfn = s%ncfn + 1
                s%rmax = 2.0_dp
                s%tn = s%told
                call unpredict(s)
                if (fatal) then
                    s%kflag = KF_SINGULAR
                    exit attempt
                end if
                if (abs(s%h) <= max(s%hmin*1.00001_dp, hfloor(s)) .or. ncf == MXNCF) then
                    s%kflag = KF_CONV
                    if (singular) s%kflag = KF_SINGULAR
                    exit attempt
                end if
                s%ipup = newton
                call rescale(s, 0.25_dp, .true.)
                cycle attempt
            end if

            ! converged: local error test
            s%jcur = .false.
            if (m == 0) then
                dsm = del/s%tesco(2, s%nq, s%meth)
            else
                dsm = vmnorm(s%n, s%acor, s%rewt)/s%tesco(2, s%nq, s%meth)
            end if
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
                ! ---- successful step
                s%kflag = KF_OK
                s%nst = s%nst + 1
                s%hu = s%h
                s%nqu = s%nq
                s%mused = s%meth
                call add_correction(s%yh, s%n, s%el, s%acor, s%l)
                if (s%ns > 0) call add_correction(s%zh, s%nsn, s%el, s%sacor, s%l)
                switched = .false.
                s%icount = s%icount - 1
                if (s%icount < 0) then
                    if (s%meth == METHOD_ADAMS) then
                        ! would BDF allow a much larger step?
                        if (s%nq <= 5 .and. .not. s%adams_only) then
                            if (dsm > 100.0_dp*pnorm*UROUND .and. s%pdest /= 0.0_dp) then
                                exsm = 1.0_dp/s%l
                                rh1 = 1.0_dp/(1.2_dp*dsm**exsm + 1.2e-6_dp)
                                rh1it = 2.0_dp*rh1
                                pdh = s%pdlast*abs(s%h)
                                if (pdh*rh1 > 1.0e-5_dp) rh1it = SM1(s%nq)/pdh
                                rh1 = min(rh1, rh1it)
                                if (s%nq > s%mxords) then
                                    nqm = s%mxords
                                    lm = nqm + 1
                                    exm = 1.0_dp/lm
                                    dm = vmnorm(s%n, s%yh(:, lm + 1), s%rewt)/s%cm2(nqm)
                                    rh2 = 1.0_dp/(1.2_dp*dm**exm + 1.2e-6_dp)
                                else
                                    dm = dsm*(s%cm1(s%nq)/s%cm2(s%nq))
                                    rh2 = 1.0_dp/(1.2_dp*dm**exsm + 1.2e-6_dp)
                                    nqm = s%nq
                                end if
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
                        end if
                    else
                        ! would Adams allow a step not smaller than BDF's?
                        exsm = 1.0_dp/s%l
                        if (s%mxordn < s%nq) then
                            nqm = s%mxordn
                            lm = nqm + 1
                            exm = 1.0_dp/lm
                            dm = vmnorm(s%n, s%yh(:, lm + 1), s%rewt)/s%cm1(nqm)
                            rh1 = 1.0_dp/(1.2_dp*dm**exm + 1.2e-6_dp)
                        else
                            dm = dsm*(s%cm2(s%nq)/s%cm1(s%nq))
                            rh1 = 1.0_dp/(1.2_dp*dm**exsm + 1.2e-6_dp)
                            nqm = s%nq
                            exm = exsm
                        end if
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
                    end if
                end if
                if (switched) then
                    s%icount = SWITCH_WAIT
                    s%pdlast = 0.0_dp
                    s%l = s%nq + 1
                    call rescale(s, rh, .true.)
                    s%rmax = 10.0_dp
                    exit attempt
                end if

                s%ialth = s%ialth - 1
                if (s%ialth == 0) then
                    call choose_order(s, dsm, .true., newq, rh)
                    if (newq < 0) exit attempt        ! keep order and step
                    if (newq /= s%nq) then
                        s%nq = newq
                        s%l = newq + 1
                        call load_el(s)
                    end if
                    call rescale(s, rh, .true.)
                    s%rmax = 10.0_dp
                    exit attempt
                end if
                if (s%ialth == 1 .and. s%l /= s%lmax) then
                    s%yh(:, s%lmax) = s%acor          ! kept for the order-increase test
                    if (s%ns > 0) s%zh(:, s%lmax) = s%sacor
                end if
                exit attempt
            end if

            ! ---- error test failed
            s%netf = s%netf + 1
            s%kflag = s%kflag - 1
            s%tn = s%told
            call unpredict(s)
            s%rmax = 2.0_dp
            if (abs(s%h) <= max(s%hmin*1.00001_dp, hfloor(s))) then
                s%kflag = KF_ERRTEST
                exit attempt
            end if
            if (s%kflag <= -3) then
                if (s%kflag <= -MXNEF) then
                    s%kflag = KF_ERRTEST
                    exit attempt
                end if
                ! repeated failures: restart at order 1 from a fresh derivative, h/10
                rh = max(s%hmin/abs(s%h), 0.1_dp)
                s%h = s%h*rh
                s%y = s%yh(:, 1)
                call sys%rhs(s%tn, s%y, s%savf, stat)
                s%nfe = s%nfe + 1
                if (stat%code /= STATUS_OK) then
                    call prefix_time(stat, s%tn)
                    s%kflag = KF_FATAL
                    exit attempt
                end if
                s%yh(:, 2) = s%h*s%savf
                if (s%ns > 0) then
                    call sens_slope(s, sys, s%tn, s%y, stat)
                    if (stat%code /= STATUS_OK) then
                        call prefix_time(stat, s%tn)
                        s%kflag = KF_FATAL
                        exit attempt
                    end if
                    s%zh(:, 2) = s%h*s%zh(:, 2)
                end if
                s%ipup = s%meth == METHOD_BDF
                s%ialth = 5
                if (s%nq /= 1) then
                    s%nq = 1
                    s%l = 2
                    call load_el(s)
                end if
                cycle attempt
            end if
            call choose_order(s, dsm, .false., newq, rh)
            if (newq /= s%nq) then
                s%nq = newq
                s%l = newq + 1
                call load_el(s)
            end if
            call rescale(s, rh, .true.)
        end do attempt

        if (s%kflag == KF_OK) then
            rm = 1.0_dp/s%tesco(2, s%nqu, s%mused)
            call scale_vec(s%n, rm, s%acor)
        end if
        s%hold = s%h
        s%jstart = 1
    end subroutine take_step

    !> Undo the prediction after a right-hand-side failure and mark the step fatal.
    subroutine fail_fatal(s, stat)
        type(lsoda_t), intent(inout) :: s
        type(status_t), intent(inout) :: stat
        s%tn = s%told
        call unpredict(s)
        call prefix_time(stat, s%tn)
        s%kflag = KF_FATAL
        s%hold = s%h
    end subroutine fail_fatal

    !> Smallest |h| worth trying at tn (a few units of roundoff of t).
    pure real(dp) function hfloor(s)
        type(lsoda_t), intent(in) :: s
        hfloor = 4.0_dp*UROUND*abs(s%tn)
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
        if (use_hmin) rh = max(rh, s%hmin/abs(s%h))
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

    !> yh <- yh * Pascal triangle (Taylor predictor to tn + h).
    subroutine predict(s)
        type(lsoda_t), intent(inout) :: s
        call pascal(s%yh, s%n, s%nq)
        if (s%ns > 0) call pascal(s%zh, s%nsn, s%nq)
    end subroutine predict

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
    !! solution and savf = f(tn, y).
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
            call sys%factor_iteration(s%tn, s%y, hl0, s%rewt, pn, singular, stat)
            if (stat%code /= STATUS_OK) return
            s%pdnorm = pn
            s%nlu = s%nlu + 1
            return
        end if
        if (sys%has_jacobian()) then
            call sys%jacobian(s%tn, s%y, s%wm, stat)
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
                call sys%rhs(s%tn, s%y, s%ftem, stat)
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

    !> The sensitivities' corrector at the step's converged point (tn, y): sacor with
    !!     (I - h l0 J) sacor = h (J zh1 + df/dp) - zh2
    !! (zh predicted; J and df/dp exact at (tn, y)), solved by a chord iteration whose
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
        call sys%sens_point(s%tn, s%y, s%sdfdp, stat)
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
        call check_in_step(s, t, 'lsoda dense', stat)
        if (stat%code /= STATUS_OK) then
            dky = yh(:, 1)
            return
        end if
        sc = 0.0_dp
        if (s%h /= 0.0_dp) sc = (t - s%tn)/s%h
        call horner(yh, m, s%nq, s%h, sc, k, dky)
    end subroutine interpolate

    !> LSODA_ERR_ILLEGAL_INPUT, '<who>: t = ... is outside the last step [...]', when t is
    !! not within the last step (up to roundoff), else STATUS_OK.
    subroutine check_in_step(s, t, who, stat)
        type(lsoda_t), intent(in) :: s
        real(dp), intent(in) :: t
        character(len=*), intent(in) :: who
        type(status_t), intent(out) :: stat
        real(dp) :: tp, tol
        character(len=200) :: buf
        stat%code = STATUS_OK
        tol = 100.0_dp*UROUND*(abs(s%tn) + abs(s%hu))
        tp = s%tn - s%hu
        if (min(tp, s%tn) - tol > t .or. t > max(tp, s%tn) + tol) then
            write (buf, '(a,es15.7e3,a,es15.7e3,a,es15.7e3,a)') ': t = ', t, &
                ' is outside the last step [', min(tp, s%tn), ', ', max(tp, s%tn), ']'
            call set_error(stat, LSODA_ERR_ILLEGAL_INPUT, who//trim(buf))
        end if
    end subroutine check_in_step

    !> The k-th derivative of the polynomial of a Nordsieck array yh (order nq, step h) at
    !! the point sc h from the step's end.
    pure subroutine horner(yh, m, nq, h, sc, k, dky)
        integer, intent(in) :: m                        !! rows
        real(dp), intent(in) :: yh(m, LMAX_ALL)         !! Nordsieck array
        integer, intent(in) :: nq, k                    !! order, derivative
        real(dp), intent(in) :: h, sc                   !! step, (t - tn)/h
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

    !> Prefix a message with the time reached.
    subroutine prefix_time(stat, t)
        type(status_t), intent(inout) :: stat
        real(dp), intent(in) :: t
        character(len=40) :: buf
        write (buf, '(a,es15.7e3,a)') 'at t = ', t, ': '
        if (allocated(stat%msg)) then
            stat%msg = trim(buf)//' '//stat%msg
        else
            stat%msg = trim(buf)//' (no message)'
        end if
    end subroutine prefix_time

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
