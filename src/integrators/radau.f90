!> The three-stage Radau IIA method of order 5 for stiff y' = f(t, y), with its own error
!! estimate, step-size control and dense output.
!!
!! Algorithm (written from the published description: E. Hairer and G. Wanner, "Solving
!! Ordinary Differential Equations II", 2nd ed., Springer 1996, section IV.8; the method of
!! Ehle 1969 and Butcher 1964; the step-size controller of Gustafsson 1994):
!!
!! * The method: collocation at the Radau points c = ((4 - sqrt 6)/10, (4 + sqrt 6)/10, 1)
!!   (A from the collocation conditions, radau_coefficients).  Stiffly accurate and
!!   L-stable: a stiff mode, oscillating or not, is damped in one step of any size, so the
!!   step follows the slow motion only.
!! * The stage equations Z = h (A x I) F(Z), z_i = Y_i - y0, by a simplified Newton
!!   iteration with one Jacobian J per step.  With A^-1 = T diag(gamma, [alpha -beta; beta
!!   alpha]) T^-1 and W = (T^-1 x I) Z the 3n x 3n linear system falls apart into a real
!!   n x n system with (gamma/h I - J) and a complex one with ((alpha + i beta)/h I - J),
!!   each factored once by LAPACK (module lapack_wrap: dgetrf, zgetrf).  Starting values
!!   come from the previous step's collocation polynomial extrapolated to the new nodes.
!!   The iteration stops when eta_k ||dW_k|| <= fnewt (eta_k = theta_k/(1 - theta_k),
!!   theta_k the observed contraction); it is abandoned and the step halved (0.5 h) when
!!   theta_k >= 1 or when the contraction predicts no convergence within NEWTON_MAX
!!   iterations.
!! * Jacobian and factorisations are kept while they serve: after an accepted step J is
!!   recomputed only if the Newton contraction was slower than THETA_JAC; the factors are
!!   kept while h changes by less than the factors H_KEEP_LO ... H_KEEP_HI (h then kept).
!!   J is the system's analytic Jacobian when it has one, else forward differences.
!! * Error estimate: the embedded formula of order 3, y_hat - y1 = gamma0 h f(t0, y0) +
!!   sum e_i z_i (gamma0 = 1/gamma), filtered by (I - h gamma0 J)^-1 so that the stiff
!!   components, which the method damps, do not inflate it; on the first step and after a
!!   rejection an estimate >= 1 is filtered once more through f(t0, y0 + err).  Norm: the
!!   root mean square of err_i/(atol_i + rtol max(|y0_i|, |y1_i|)).
!! * Tolerances: the estimate is held to rtol' = 10 rtol (at most 1e-2), atol' = atol
!!   rtol'/rtol, so that the global error is about rtol at every rtol.  RADAU5 holds it to
!!   0.1 rtol^(2/3), because on non-stiff problems the true local error, of order 5, lies
!!   far below the order-3 estimate at tight tolerances; on stiff problems the stiff
!!   components' local error has the order of the estimate (order reduction to the stage
!!   order), and with 0.1 rtol^(2/3) the global error grows like rtol^(2/3), where with
!!   10 rtol it stays about rtol (the measured figures: doc/performance.md).
!! * Step size: h_new = h fac err^(-1/4), fac = 0.9 (2 NEWTON_MAX + 1)/(2 NEWTON_MAX +
!!   newton iterations), limited to h/8 ... 5 h, and after an accepted step the smaller of
!!   that and Gustafsson's predictive choice h (h/h_prev) (err_prev/err^2)^(1/4); no
!!   increase right after a rejection.  Never past tcrit.
!! * Output: the collocation polynomial of the last step (degree 3 through y0 and the three
!!   stage values) gives the solution anywhere in it (dense, order 3 uniformly, 5 at the
!!   step ends).
!! * Forward sensitivities (sens_init, sens_dense), by the staggered direct method
!!   (Caracotsios & Stewart 1985; Maly & Petzold 1996): once a step's stage values are
!!   found (and, by default, the step accepted), the collocation equations are solved for the
!!   sensitivities' stage increments, Zs = h (A x I) Fs, Fs_i = J_i (s0 + Zs_i) + df/dp_i,
!!   with the exact J_i and df/dp_i at the three stage values, by the step's own simplified
!!   Newton iteration (its factored real and complex matrices; residuals exact), and, should
!!   it contract too slowly, by a direct solve of the 3n x 3n system.  The sensitivities at
!!   the step's end are s0 + Zs_3 (the method is stiffly accurate), and their collocation
!!   polynomial their dense output.  They take part in the error estimate only when asked
!!   (error_control), through the same embedded formula.
!!
!! The code: integrate and step are integrator_t's (module ode_system); this module gives
!! them the first step size (radau_start) and one accepted step (radau_one_step: the
!! Jacobian and the factors, the stage equations by newton, the error estimate, then the
!! step accepted or retried), and the dense output of the collocation polynomial.
!!
!! All state lives in a `radau_t` object (with what every integrator keeps, its
!! integrator_t part), so independent integrations can be interleaved.
!! No routine stops the program: every failure is returned in a status_t with one of the
!! RADAU_ERR_* codes (or the code the right-hand side returned) and a message naming the
!! cause and the time reached; the solution up to the failure is kept.
module radau
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, RADAU_ERR_MAX_STEPS, &
        RADAU_ERR_TOO_MUCH_ACCURACY, RADAU_ERR_STEP_TOO_SMALL, RADAU_ERR_ILLEGAL_INPUT, &
        RADAU_ERR_SINGULAR
    use ode_system, only: ode_system_t, integrator_t, integrator_stats_t, integrator_id_t, &
        common_stats, METHOD_RADAU
    use lapack_wrap, only: la_lu_factor, la_lu_solve, la_zlu_factor, la_zlu_solve
    use unused_arg, only: unused
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    !> Method code of this integrator in integrator_stats_t (module ode_system).
    public :: METHOD_RADAU

    real(dp), parameter :: UROUND = epsilon(1.0_dp)
    integer, parameter :: NEWTON_MAX = 7          !! Newton iterations per attempt
    real(dp), parameter :: SAFETY = 0.9_dp        !! safety factor of the step-size choice
    real(dp), parameter :: FAC_UP = 5.0_dp        !! largest step growth per step
    real(dp), parameter :: FAC_DOWN = 0.125_dp    !! largest step reduction per step
    real(dp), parameter :: THETA_JAC = 1.0e-3_dp  !! recompute J after a slower contraction
    real(dp), parameter :: H_KEEP_LO = 1.0_dp, H_KEEP_HI = 1.2_dp  !! keep h and the factors
    integer, parameter :: MAX_FAILS = 50          !! consecutive failed attempts of one step
    integer, parameter :: SENS_MAXIT = 10          !! sensitivity iterations before a direct solve
    real(dp), parameter :: SENS_CONV = 0.1_dp      !! their test: this part of the state's
    !> The local error estimate is held to TOL_FACTOR rtol (at most TOL_MAX): see the header.
    real(dp), parameter :: TOL_FACTOR = 10.0_dp, TOL_MAX = 1.0e-2_dp

    !> The coefficients of the method (radau_coefficients).
    type, public :: radau_coeffs_t
        real(dp) :: c(3) = 0.0_dp               !! nodes
        real(dp) :: a(3, 3) = 0.0_dp            !! Butcher matrix A
        real(dp) :: ainv(3, 3) = 0.0_dp         !! A^-1
        real(dp) :: gam = 0.0_dp                !! real eigenvalue of A^-1
        real(dp) :: alpha = 0.0_dp, beta = 0.0_dp  !! complex pair alpha +- i beta of A^-1
        !> A^-1 = T diag(gam, [alpha -beta; beta alpha]) T^-1
        real(dp) :: t(3, 3) = 0.0_dp
        real(dp) :: tinv(3, 3) = 0.0_dp         !! T^-1
        real(dp) :: gam0 = 0.0_dp               !! 1/gam, the embedded formula's weight of f(t0, y0)
        real(dp) :: e(3) = 0.0_dp               !! y_hat - y1 = gam0 h f0 + sum e_i z_i
        real(dp) :: lag(3) = 0.0_dp             !! 1/(c_j prod_{m /= j} (c_j - c_m)) (dense output)
    end type radau_coeffs_t


    !> One integration by Radau IIA: the method's coefficients, the solution and the last
    !! step (dense output, starting values), the Jacobian and the factored iteration
    !! matrices, the step-size control's history and the sensitivities' (what every
    !! integrator keeps, as t, h, the tolerances and the counters, is integrator_t's; its
    !! rtol and atol are the transformed tolerances, see the header).
    type, extends(integrator_t), public :: radau_t
        private
        type(radau_coeffs_t) :: cf              !! the method's coefficients
        real(dp) :: fnewt = 0.0_dp              !! the Newton iteration's threshold (scaled norm)
        real(dp), allocatable :: y(:)           !! (n) the solution at t (units of y)
        real(dp), allocatable :: f0(:)          !! (n) f(t, y) (units of y per unit of t)
        ! the last accepted step [t_old, t] (its size is hu)
        real(dp) :: t_old = 0.0_dp              !! its start
        real(dp), allocatable :: y_old(:)       !! (n) the solution at its start
        real(dp), allocatable :: z_old(:, :)    !! (n, 3) its stage increments Y_i - y_old
        logical :: have_step = .false.          !! a step has been accepted since init
        ! the Jacobian and the factors
        real(dp), allocatable :: jac(:, :)      !! (n, n) J (per unit of t)
        real(dp), allocatable :: e1(:, :)       !! (n, n) gam/h I - J, then its LU factors
        complex(dp), allocatable :: e2(:, :)    !! (n, n) (alpha + i beta)/h I - J, factored
        integer, allocatable :: ip1(:)          !! (n) the pivots of e1
        integer, allocatable :: ip2(:)          !! (n) the pivots of e2
        logical :: jac_current = .false.        !! jac was evaluated at (t, y)
        logical :: need_jac = .true.            !! J is to be evaluated before the next attempt
        logical :: need_lu = .true.             !! e1, e2 are to be factored anew
        real(dp) :: h_lu = 0.0_dp               !! the h of the factors (units of t)
        ! the history of the control
        logical :: first = .true.               !! no step accepted yet
        logical :: rejected = .false.           !! the last attempt was rejected
        real(dp) :: eta = 1.0_dp                !! Newton: theta/(1 - theta) of the last step
        real(dp) :: theta = 0.0_dp              !! Newton: contraction of the last attempt
        real(dp) :: h_acc = 0.0_dp              !! Gustafsson: the last accepted h
        real(dp) :: err_acc = 1.0e-2_dp         !! Gustafsson: its error (at least 1e-2)
        integer :: nit = 0                      !! simplified Newton iterations since init
        ! forward sensitivities (sens_init)
        real(dp), allocatable :: sy(:, :)       !! (n, ns) the sensitivities at t
        real(dp), allocatable :: sy_old(:, :)   !! (n, ns) at the last step's start
        real(dp), allocatable :: zs_old(:, :, :)    !! (n, ns, 3) its stage increments
        real(dp), allocatable :: sf0(:, :)      !! (n, ns) their slope at t (error control only)
    contains
        procedure :: init => radau_init
        procedure :: dense_at => radau_dense_at
        procedure :: stats => radau_get_stats
        procedure :: sens_init => radau_sens_init
        procedure :: sens_dense_at => radau_sens_dense_at
        procedure :: start => radau_start
        procedure :: one_step => radau_one_step
        procedure :: solution => radau_solution
        procedure :: at_tcrit => radau_at_tcrit
        procedure :: identity => radau_identity
    end type radau_t

    public :: radau_coefficients

contains

    ! ------------------------------------------------------------------------------------
    ! The method's coefficients
    ! ------------------------------------------------------------------------------------

    !> The coefficients of the three-stage Radau IIA method, computed from its nodes (the
    !! zeros of d^2/dx^2 (x^2 (x - 1)^3)): A from the collocation conditions
    !! sum_j a_ij c_j^(k-1) = c_i^k/k (k = 1, 2, 3); the eigen-decomposition of A^-1 (one
    !! real eigenvalue gam, a complex pair alpha +- i beta; T from the eigenvectors: the real
    !! one, then the real part and minus the imaginary part of the one for alpha + i beta);
    !! the embedded formula's weights b_hat (quadrature order 3 on the nodes 0, c with
    !! b_hat0 = gam0 = 1/gam) turned into the coefficients e = A^-T (b_hat - b) of the
    !! stage increments; the Lagrange denominators of the collocation polynomial.
    pure function radau_coefficients() result(cf)
        type(radau_coeffs_t) :: cf
        real(dp) :: v(3, 3), d(3, 3), vinv(3, 3), m(3, 3), tr, m2, dt, lam, p, dp_, s6, bh(3)
        complex(dp) :: mc(3, 3), vc(3), lc
        integer :: i, j, k, it
        s6 = sqrt(6.0_dp)
        cf%c = [(4.0_dp - s6)/10.0_dp, (4.0_dp + s6)/10.0_dp, 1.0_dp]
        do k = 1, 3
            v(:, k) = cf%c**(k - 1)             ! v(j, k) = c_j^(k-1)
            d(:, k) = cf%c**k/k
        end do
        vinv = inverse3(v)
        cf%a = matmul(d, vinv)
        cf%ainv = inverse3(cf%a)
        m = cf%ainv
        ! characteristic polynomial lam^3 - tr lam^2 + m2 lam - dt
        tr = m(1, 1) + m(2, 2) + m(3, 3)
        m2 = m(1, 1)*m(2, 2) - m(1, 2)*m(2, 1) + m(1, 1)*m(3, 3) - m(1, 3)*m(3, 1) &
             + m(2, 2)*m(3, 3) - m(2, 3)*m(3, 2)
        dt = det3(m)
        ! its one real zero by Newton from above (the cubic is convex beyond its zero)
        lam = tr
        do it = 1, 100
            p = ((lam - tr)*lam + m2)*lam - dt
            dp_ = (3.0_dp*lam - 2.0_dp*tr)*lam + m2
            if (dp_ == 0.0_dp) exit
            if (abs(p/dp_) <= 4.0_dp*UROUND*abs(lam)) then
                lam = lam - p/dp_
                exit
            end if
            lam = lam - p/dp_
        end do
        cf%gam = lam
        cf%alpha = 0.5_dp*(tr - lam)
        cf%beta = sqrt(max(0.0_dp, dt/lam - cf%alpha**2))
        ! real eigenvector: null vector of m - gam I (cross product of two rows)
        d = m
        do i = 1, 3
            d(i, i) = d(i, i) - cf%gam
        end do
        cf%t(:, 1) = best_cross(d)
        ! complex eigenvector for alpha + i beta
        lc = cmplx(cf%alpha, cf%beta, kind=dp)
        mc = cmplx(m, 0.0_dp, kind=dp)
        do i = 1, 3
            mc(i, i) = mc(i, i) - lc
        end do
        vc = best_ccross(mc)
        cf%t(:, 2) = real(vc)
        cf%t(:, 3) = -aimag(vc)
        cf%tinv = inverse3(cf%t)
        ! embedded formula: b_hat from sum b_hat_i c_i^(k-1) = 1/k - gam0 [k = 1]
        cf%gam0 = 1.0_dp/cf%gam
        bh = matmul([1.0_dp - cf%gam0, 0.5_dp, 1.0_dp/3.0_dp], vinv)
        bh = bh - cf%a(3, :)                    ! b = last row of A (stiffly accurate)
        cf%e = matmul(bh, cf%ainv)
        do j = 1, 3
            p = cf%c(j)
            do k = 1, 3
                if (k /= j) p = p*(cf%c(j) - cf%c(k))
            end do
            cf%lag(j) = 1.0_dp/p
        end do
    end function radau_coefficients

    pure function det3(a) result(d)
        real(dp), intent(in) :: a(3, 3)
        real(dp) :: d
        d = a(1, 1)*(a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)) - a(1, 2)*(a(2, 1)*a(3, 3) - &
            a(2, 3)*a(3, 1)) + a(1, 3)*(a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1))
    end function det3

    !> Inverse of a 3 x 3 matrix by cofactors (the matrices here are far from singular).
    pure function inverse3(a) result(b)
        real(dp), intent(in) :: a(3, 3)
        real(dp) :: b(3, 3)
        b(1, :) = [a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2), a(1, 3)*a(3, 2) - a(1, 2)*a(3, 3), &
                   a(1, 2)*a(2, 3) - a(1, 3)*a(2, 2)]
        b(2, :) = [a(2, 3)*a(3, 1) - a(2, 1)*a(3, 3), a(1, 1)*a(3, 3) - a(1, 3)*a(3, 1), &
                   a(1, 3)*a(2, 1) - a(1, 1)*a(2, 3)]
        b(3, :) = [a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1), a(1, 2)*a(3, 1) - a(1, 1)*a(3, 2), &
                   a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)]
        b = b/det3(a)
    end function inverse3

    !> Null vector of a real 3 x 3 matrix of rank 2: the largest cross product of two rows.
    pure function best_cross(d) result(v)
        real(dp), intent(in) :: d(3, 3)
        real(dp) :: v(3), w(3)
        integer :: i, j
        v = 0.0_dp
        do i = 1, 2
            do j = i + 1, 3
                w = [d(i, 2)*d(j, 3) - d(i, 3)*d(j, 2), d(i, 3)*d(j, 1) - d(i, 1)*d(j, 3), &
                     d(i, 1)*d(j, 2) - d(i, 2)*d(j, 1)]
                if (norm2(w) > norm2(v)) v = w
            end do
        end do
        v = v/norm2(v)
    end function best_cross

    !> Null vector of a complex 3 x 3 matrix of rank 2 (bilinear cross product of two rows).
    pure function best_ccross(d) result(v)
        complex(dp), intent(in) :: d(3, 3)
        complex(dp) :: v(3), w(3)
        integer :: i, j
        v = (0.0_dp, 0.0_dp)
        do i = 1, 2
            do j = i + 1, 3
                w = [d(i, 2)*d(j, 3) - d(i, 3)*d(j, 2), d(i, 3)*d(j, 1) - d(i, 1)*d(j, 3), &
                     d(i, 1)*d(j, 2) - d(i, 2)*d(j, 1)]
                if (sum(abs(w)**2) > sum(abs(v)**2)) v = w
            end do
        end do
        v = v/sqrt(sum(abs(v)**2))
    end function best_ccross

    ! ------------------------------------------------------------------------------------
    ! Public routines (integrate, step and set_tcrit are integrator_t's)
    ! ------------------------------------------------------------------------------------

    !> Start an integration at (t0, y0).
    !!
    !! sys       [in,out] the right-hand side; called once here for f(t0, y0).
    !! t0        [in]  initial time.
    !! y0        [in]  initial state, size n >= 1.
    !! rtol      [in]  relative tolerance, > 0 (transformed internally, see the header).
    !! atol      [in]  absolute tolerance, size 1 or n, each >= 0 and finite.
    !! stat      [out] STATUS_OK; RADAU_ERR_ILLEGAL_INPUT for bad arguments;
    !!                 RADAU_ERR_TOO_MUCH_ACCURACY for rtol below 1e-14 (the transformed
    !!                 tolerance would drown in roundoff); or the right-hand side's code.
    !! tcrit     [in, optional] time the integration must never step past.
    !! h0        [in, optional] first step to try (sign ignored); default: estimated from
    !!                 f(t0, y0), the tolerances and the first output time.
    !! hmax      [in, optional] largest |h| (> 0); default unlimited.
    !! max_steps [in, optional] most steps in one call of integrate (default 500000).
    subroutine radau_init(s, sys, t0, y0, rtol, atol, stat, tcrit, h0, hmax, max_steps)
        class(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t0, y0(:), rtol, atol(:)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: tcrit, h0, hmax
        integer, intent(in), optional :: max_steps
        integer :: n
        real(dp) :: quot
        character(len=120) :: buf

        n = size(y0)
        call s%init_common(t0, n, atol, stat, tcrit, h0, hmax, max_steps)
        if (stat%code /= STATUS_OK) return
        if (.not. (rtol > 0.0_dp .and. rtol < 1.0_dp)) then
            write (buf, '(a,es10.3,a)') 'radau init: rtol = ', rtol, ' must lie in (0, 1)'
            call set_error(stat, RADAU_ERR_ILLEGAL_INPUT, trim(buf))
            return
        end if
        if (rtol < 1.0e-14_dp) then
            write (buf, '(a,es10.3,a)') 'radau init: too much accuracy requested: rtol = ', &
                rtol, ' is below 1e-14'
            call set_error(stat, RADAU_ERR_TOO_MUCH_ACCURACY, trim(buf))
            return
        end if

        s%cf = radau_coefficients()
        ! transformed tolerances (see the header)
        s%rtol = min(TOL_FACTOR*rtol, TOL_MAX)
        quot = s%rtol/rtol
        s%atol = s%atol*quot
        s%fnewt = max(10.0_dp*UROUND/s%rtol, min(0.03_dp, sqrt(s%rtol)))
        call alloc_work(s, n)

        s%y = y0
        s%have_step = .false.
        s%jac_current = .false.
        s%need_jac = .true.
        s%need_lu = .true.
        s%h_lu = 0.0_dp
        s%first = .true.
        s%rejected = .false.
        s%eta = 1.0_dp
        s%theta = 0.0_dp
        s%h_acc = 0.0_dp
        s%err_acc = 1.0e-2_dp
        s%nit = 0
        call s%start_rhs(sys, s%y, s%f0, stat)
        if (stat%code /= STATUS_OK) return
        s%ready = .true.
    end subroutine radau_init

    subroutine alloc_work(s, n)
        type(radau_t), intent(inout) :: s
        integer, intent(in) :: n
        if (allocated(s%y)) then
            if (size(s%y) == n) return
            deallocate (s%y, s%f0, s%y_old, s%z_old, s%jac, s%e1, s%e2, s%ip1, s%ip2)
        end if
        allocate (s%y(n), s%f0(n), s%y_old(n), s%z_old(n, 3), s%jac(n, n), s%e1(n, n), &
                  s%e2(n, n), s%ip1(n), s%ip2(n))
        s%y_old = 0.0_dp
        s%z_old = 0.0_dp
        s%jac = 0.0_dp
    end subroutine alloc_work

    !> k-th derivative (k = 0 or 1) of the last step's collocation polynomial at t (dense of
    !! integrator_t checks the integration and dky first).
    !!
    !! t    [in]  time in [t_current - h_last, t_current] (roundoff tolerated); before the
    !!            first step only t = t0.
    !! dky  [out] size n: d^k y/dt^k at t.
    !! stat [out] STATUS_OK or RADAU_ERR_ILLEGAL_INPUT (t outside the step, bad k).
    subroutine radau_dense_at(s, t, k, dky, stat)
        class(radau_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(:)
        type(status_t), intent(out) :: stat
        real(dp) :: x
        dky = 0.0_dp
        call dense_position(s, t, k, 'dense', x, stat)
        if (stat%code /= STATUS_OK) return
        call collocation(s, x, k, s%n, s%y, s%f0, s%y_old, s%z_old, dky)
    end subroutine radau_dense_at

    !> Counters and step sizes (see integrator_stats_t).
    pure function radau_get_stats(s) result(st)
        class(radau_t), intent(in) :: s
        type(integrator_stats_t) :: st
        st = common_stats(s)
        st%newton_iterations = s%nit
        st%method_switches = 0
        st%method_last = METHOD_RADAU
        st%order_last = 5
        st%method_next = METHOD_RADAU
        st%order_next = 5
    end function radau_get_stats

    !> Radau's name and status codes for the procedures of integrator_t.
    pure function radau_identity(s) result(id)
        class(radau_t), intent(in) :: s
        type(integrator_id_t) :: id
        call unused(s)
        id = integrator_id_t('radau', RADAU_ERR_ILLEGAL_INPUT, RADAU_ERR_MAX_STEPS)
    end function radau_identity

    !> The solution at t.
    pure subroutine radau_solution(s, y)
        class(radau_t), intent(in) :: s
        real(dp), intent(out) :: y(:)       !! (n)
        y = s%y
    end subroutine radau_solution

    !> Start forward sensitivities (see the module header): after init, before the first
    !! step.
    !!
    !! s0    [in]  (n, ns) the sensitivities at t0, ns >= 1.
    !! stat  [out] STATUS_OK; RADAU_ERR_ILLEGAL_INPUT (no init, the integration has started,
    !!             a bad shape or scale); or the system's code from its terms.
    !! scale [in, optional] (ns) the size of sensitivity k against the state's: its absolute
    !!             tolerance is atol scale(k) (default 1), > 0; the transformed atol, and
    !!             for an atol of 0 the transformed rtol.
    !! error_control [in, optional] .true.: the sensitivities take part in the error
    !!             estimate (default .false.: the state's steps alone).
    subroutine radau_sens_init(s, sys, s0, stat, scale, error_control)
        class(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: s0(:, :)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: scale(:)
        logical, intent(in), optional :: error_control
        integer :: n, ns
        call s%sens_init_common(s0, s%rtol, stat, scale, error_control)
        if (stat%code /= STATUS_OK) return
        n = s%n
        ns = s%ns
        if (allocated(s%sy)) deallocate (s%sy, s%sy_old, s%zs_old, s%sf0)
        allocate (s%sy(n, ns), s%sy_old(n, ns), s%zs_old(n, ns, 3), s%sf0(n, ns))
        s%sy = s0
        s%sy_old = s0
        s%zs_old = 0.0_dp
        s%sf0 = 0.0_dp
        if (s%sens_errcon) then
            block
                real(dp) :: jm(n, n), pk(n, ns)
                call stage_terms(s, sys, s%t, s%y, jm, pk, stat)
                if (stat%code /= STATUS_OK) then
                    s%ns = 0
                    return
                end if
                s%sf0 = matmul(jm, s%sy) + pk
            end block
        end if
    end subroutine radau_sens_init


    !> The sensitivities (k = 0) or their derivative (k = 1) at t within the last step
    !! (sens_dense of integrator_t checks ds first).
    !!
    !! ds   [out] (n, ns).
    !! stat [out] STATUS_OK or RADAU_ERR_ILLEGAL_INPUT (t outside the step, a bad k).
    subroutine radau_sens_dense_at(s, t, k, ds, stat)
        class(radau_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: ds(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: x
        ds = 0.0_dp
        call dense_position(s, t, k, 'sens_dense', x, stat)
        if (stat%code /= STATUS_OK) return
        call collocation(s, x, k, s%n*s%ns, s%sy, s%sf0, s%sy_old, s%zs_old, ds)
    end subroutine radau_sens_dense_at

    ! ------------------------------------------------------------------------------------
    ! The step
    ! ------------------------------------------------------------------------------------

    !> The first step size: the caller's h0, else from an explicit Euler probe (Hairer,
    !! Norsett & Wanner I, sec. II.4): h = min(100 h_a, h_b) with h_a = 0.01 ||y0||/||f0||
    !! and h_b = (0.01/max(||f0||, ||f'||))^(1/4), f' estimated by the Euler step of size
    !! h_a, the norms in the error weights; limited by |tout - t0|, hmax and tcrit.
    subroutine radau_start(s, sys, tout, have_tout, stat)
        class(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: tout                !! a time the caller wants to reach
        logical, intent(in) :: have_tout            !! tout is given (else t + 1 stands for it)
        type(status_t), intent(out) :: stat
        real(dp) :: d0, d1, d2, ha, hb, h, w(s%n), y1(s%n), f1(s%n), span, th
        stat%code = STATUS_OK
        th = tout
        if (.not. have_tout) th = s%t + 1.0_dp
        span = abs(th - s%t)
        if (s%have_tcrit) then
            if (s%tcrit /= s%t) span = min(span, abs(s%tcrit - s%t))
        end if
        if (s%h0_user > 0.0_dp) then
            h = s%h0_user
        else
            w = s%atol + s%rtol*abs(s%y)
            d0 = rms(s%y/w)
            d1 = rms(s%f0/w)
            if (d0 < 1.0e-5_dp .or. d1 < 1.0e-5_dp) then
                ha = 1.0e-6_dp
            else
                ha = 0.01_dp*d0/d1
            end if
            ha = min(ha, span)
            y1 = s%y + s%dir*ha*s%f0
            call sys%rhs(s%t + s%dir*ha, y1, f1, stat)
            s%nfe = s%nfe + 1
            if (stat%code /= STATUS_OK) then
                call s%prefix_time(stat, s%t)
                return
            end if
            d2 = rms((f1 - s%f0)/w)/ha
            if (.not. ieee_is_finite(d2)) d2 = huge(1.0_dp)
            if (max(d1, d2) <= 1.0e-15_dp) then
                hb = max(1.0e-6_dp, ha*1.0e-3_dp)
            else
                hb = (0.01_dp/max(d1, d2))**0.25_dp
            end if
            h = min(100.0_dp*ha, hb)
        end if
        h = min(h, span, s%hmax)
        h = max(h, 16.0_dp*UROUND*max(1.0_dp, abs(s%t)))
        s%h = s%dir*h
        s%started = .true.
    end subroutine radau_start

    !> True when t is at tcrit up to roundoff.
    pure logical function radau_at_tcrit(s) result(at)
        class(radau_t), intent(in) :: s
        at = abs(s%tcrit - s%t) <= 4.0_dp*UROUND*max(1.0_dp, abs(s%t))
    end function radau_at_tcrit

    !> One accepted step: attempts until the Newton iteration converges and the error test
    !! passes (the step size reduced in between), then the new solution, f at it, the
    !! collocation polynomial for dense output, and the next step size.
    subroutine radau_one_step(s, sys, stat)
        class(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(out) :: stat
        real(dp) :: z(s%n, 3), sc(s%n), err, fac, quot, hnew, facgus, hh, ynew(s%n)
        real(dp) :: f1(s%n), zs(s%n, s%ns, 3), j3(s%n, s%n), p3(s%n, s%ns)
        integer :: newt, nfail
        logical :: conv
        character(len=160) :: buf
        stat%code = STATUS_OK
        nfail = 0
        do
            ! ---- step size limits: hmax, tcrit, roundoff
            hh = min(abs(s%h), s%hmax)
            if (s%have_tcrit) then
                if ((s%t + s%dir*1.01_dp*hh - s%tcrit)*s%dir >= 0.0_dp) hh = abs(s%tcrit - s%t)
            end if
            s%h = s%dir*hh
            if (hh <= 10.0_dp*UROUND*max(abs(s%t), 1.0e-300_dp) .or. nfail >= MAX_FAILS) then
                write (buf, '(a,es12.5,a,es10.3,a,i0,a)') 'radau: step size too small at t = ', &
                    s%t, ' (h = ', hh, ', ', nfail, ' failed attempts in a row)'
                call set_error(stat, RADAU_ERR_STEP_TOO_SMALL, trim(buf))
                return
            end if
            ! ---- Jacobian and factors
            if (s%need_jac .and. .not. s%jac_current) then
                call eval_jacobian(s, sys, stat)
                if (stat%code /= STATUS_OK) return
                s%need_lu = .true.
            end if
            s%need_jac = .false.
            if (s%need_lu .or. s%h /= s%h_lu) then
                call factor(s, stat)
                if (stat%code /= STATUS_OK) then
                    ! singular iteration matrix: a smaller step moves it away from J
                    nfail = nfail + 1
                    s%ncfn = s%ncfn + 1
                    if (nfail >= MAX_FAILS) then
                        call set_error(stat, RADAU_ERR_SINGULAR, 'radau: iteration matrix '// &
                            'singular at every step size tried: '//stat%msg)
                        call s%prefix_time(stat, s%t)
                        return
                    end if
                    s%h = 0.5_dp*s%h
                    s%rejected = .true.
                    cycle
                end if
            end if
            ! ---- the stage equations
            call starting_values(s, z)
            sc = s%atol + s%rtol*abs(s%y)
            call newton(s, sys, z, sc, conv, newt, hnew, stat)
            if (stat%code /= STATUS_OK) return
            if (.not. conv) then
                nfail = nfail + 1
                s%ncfn = s%ncfn + 1
                s%h = hnew
                s%rejected = .true.
                s%need_jac = .true.          ! a fresh J unless this one is current
                s%need_lu = .true.
                cycle
            end if
            ! ---- error estimate
            ynew = s%y + z(:, 3)
            sc = s%atol + s%rtol*max(abs(s%y), abs(ynew))
            call estimate(s, sys, z, sc, err, stat)
            if (stat%code /= STATUS_OK) return
            if (s%ns > 0 .and. s%sens_errcon) then
                call sens_stages(s, sys, z, zs, j3, p3, stat)
                if (stat%code /= STATUS_OK) return
                err = max(err, sens_error(s, zs))
            end if
            ! ---- new step size
            fac = min(SAFETY, SAFETY*real(2*NEWTON_MAX + 1, dp)/real(newt + 2*NEWTON_MAX, dp))
            quot = max(FAC_DOWN, min(FAC_UP, err**0.25_dp/fac))
            hnew = s%h/quot
            if (err < 1.0_dp) then
                ! accepted
                if (s%ns > 0 .and. .not. s%sens_errcon) then
                    call sens_stages(s, sys, z, zs, j3, p3, stat)
                    if (stat%code /= STATUS_OK) return
                end if
                if (.not. s%first) then
                    facgus = (s%h_acc/s%h)*(err**2/s%err_acc)**0.25_dp/SAFETY
                    facgus = max(FAC_DOWN, min(FAC_UP, facgus))
                    quot = max(quot, facgus)
                    hnew = s%h/quot
                end if
                s%h_acc = s%h
                s%err_acc = max(1.0e-2_dp, err)
                s%t_old = s%t
                s%hu = s%h
                s%y_old = s%y
                s%z_old = z
                if (s%ns > 0) then
                    s%sy_old = s%sy
                    s%zs_old = zs
                    s%sy = s%sy + zs(:, :, 3)
                    if (s%sens_errcon) s%sf0 = matmul(j3, s%sy) + p3
                end if
                s%have_step = .true.
                s%t = s%t + s%h
                if (s%have_tcrit) then
                    if (abs(s%t - s%tcrit) <= 4.0_dp*UROUND*max(1.0_dp, abs(s%tcrit))) &
                        s%t = s%tcrit
                end if
                s%y = ynew
                call sys%rhs(s%t, s%y, f1, stat)
                s%nfe = s%nfe + 1
                if (stat%code /= STATUS_OK) then
                    call s%prefix_time(stat, s%t)
                    return
                end if
                s%f0 = f1
                s%nst = s%nst + 1
                s%jac_current = .false.
                if (s%rejected) hnew = s%dir*min(abs(hnew), abs(s%h))
                s%first = .false.
                s%rejected = .false.
                ! keep J when the iteration converged fast; keep h and the factors too when
                ! the new step would differ little
                s%need_jac = s%theta > THETA_JAC
                quot = hnew/s%h
                if (.not. s%need_jac .and. quot >= H_KEEP_LO .and. quot <= H_KEEP_HI) then
                    s%need_lu = .false.
                else
                    s%h = hnew
                    s%need_lu = .true.
                end if
                s%h = s%dir*min(abs(s%h), s%hmax)
                return
            end if
            ! rejected
            nfail = nfail + 1
            s%netf = s%netf + 1
            if (s%first) then
                s%h = 0.1_dp*s%h
            else
                s%h = hnew
            end if
            s%rejected = .true.
            s%need_jac = .true.              ! a fresh J unless this one is current
            s%need_lu = .true.
        end do
    end subroutine radau_one_step

    !> The Jacobian at (t, y): the system's analytic one, or forward differences with
    !! increments sqrt(uround) max(|y_j|, atol_j/rtol) (the scale of the error weights).
    subroutine eval_jacobian(s, sys, stat)
        type(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(out) :: stat
        real(dp) :: yj(s%n), fj(s%n), del
        integer :: j
        s%nje = s%nje + 1
        if (sys%has_jacobian()) then
            call sys%jacobian(s%t, s%y, s%jac, stat)
            if (stat%code /= STATUS_OK) then
                call s%prefix_time(stat, s%t)
                return
            end if
        else
            yj = s%y
            do j = 1, s%n
                del = sqrt(UROUND)*max(abs(s%y(j)), s%atol(j)/s%rtol, 1.0e-5_dp*sqrt(UROUND))
                yj(j) = s%y(j) + del
                del = yj(j) - s%y(j)
                call sys%rhs(s%t, yj, fj, stat)
                s%nfe = s%nfe + 1
                if (stat%code /= STATUS_OK) then
                    call s%prefix_time(stat, s%t)
                    return
                end if
                s%jac(:, j) = (fj - s%f0)/del
                yj(j) = s%y(j)
            end do
        end if
        if (.not. all(ieee_is_finite(s%jac))) then
            call set_error(stat, RADAU_ERR_SINGULAR, 'radau: non-finite Jacobian')
            call s%prefix_time(stat, s%t)
            return
        end if
        s%jac_current = .true.
    end subroutine eval_jacobian

    !> The sensitivity terms at (t, y): the Jacobian jm and df/dp pk (ode_system's
    !! sens_point, sens_jv).
    subroutine stage_terms(s, sys, t, y, jm, pk, stat)
        type(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: jm(:, :), pk(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: eye(s%n, s%n)
        integer :: i
        jm = 0.0_dp
        call sys%sens_point(t, y, pk, stat)
        s%nsp = s%nsp + 1
        if (stat%code == STATUS_OK) then
            eye = 0.0_dp
            do i = 1, s%n
                eye(i, i) = 1.0_dp
            end do
            call sys%sens_jv(eye, jm, stat)
        end if
        if (stat%code /= STATUS_OK) call s%prefix_time(stat, t)
    end subroutine stage_terms

    !> The sensitivities' stage increments zs of the step from (t, y) whose state has the
    !! stage increments z (see the module header): the step's simplified Newton iteration
    !! with exact residuals, from the last step's polynomial extrapolated, to a tenth of the
    !! state's Newton threshold; a direct solve of the 3n x 3n system when it contracts too
    !! slowly.  j3, p3: the terms at the last stage (the step's end).
    subroutine sens_stages(s, sys, z, zs, j3, p3, stat)
        type(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: z(:, :)
        real(dp), intent(out) :: zs(:, :, :), j3(:, :), p3(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: jm(s%n, s%n, 3), pk(s%n, s%ns, 3), w(s%n, s%ns, 3), f(s%n, s%ns, 3)
        real(dp) :: r(s%n, s%ns, 3), dw(s%n, s%ns, 3), scs(s%n, s%ns), fac1, alphn, betan
        real(dp) :: del, delp, tol, sn, l(3)
        complex(dp) :: cv(s%n)
        integer :: i, j, k, m
        logical :: conv
        zs = 0.0_dp
        do i = 1, 3
            call stage_terms(s, sys, s%t + s%cf%c(i)*s%h, s%y + z(:, i), jm(:, :, i), &
                             pk(:, :, i), stat)
            if (stat%code /= STATUS_OK) return
        end do
        j3 = jm(:, :, 3)
        p3 = pk(:, :, 3)
        if (s%have_step) then
            do i = 1, 3
                sn = 1.0_dp + s%cf%c(i)*s%h/s%hu
                l = lagrange(s%cf, sn)
                do j = 1, 3
                    zs(:, :, i) = zs(:, :, i) + l(j)*s%zs_old(:, :, j)
                end do
                zs(:, :, i) = zs(:, :, i) - s%zs_old(:, :, 3)
            end do
        end if
        fac1 = s%cf%gam/s%h
        alphn = s%cf%alpha/s%h
        betan = s%cf%beta/s%h
        scs = s%satol + s%rtol*abs(s%sy)
        tol = SENS_CONV*s%fnewt
        call transform(s%cf%tinv, zs, w)
        conv = .false.
        delp = 0.0_dp
        do m = 1, SENS_MAXIT
            do i = 1, 3
                f(:, :, i) = matmul(jm(:, :, i), s%sy + zs(:, :, i)) + pk(:, :, i)
            end do
            call transform(s%cf%tinv, f, r)
            r(:, :, 1) = r(:, :, 1) - fac1*w(:, :, 1)
            r(:, :, 2) = r(:, :, 2) - (alphn*w(:, :, 2) - betan*w(:, :, 3))
            r(:, :, 3) = r(:, :, 3) - (betan*w(:, :, 2) + alphn*w(:, :, 3))
            do k = 1, s%ns
                dw(:, k, 1) = r(:, k, 1)
                call la_lu_solve(s%e1, s%ip1, dw(:, k, 1), stat)
                if (stat%code /= STATUS_OK) return
                cv = cmplx(r(:, k, 2), r(:, k, 3), kind=dp)
                call la_zlu_solve(s%e2, s%ip2, cv, stat)
                if (stat%code /= STATUS_OK) return
                dw(:, k, 2) = real(cv)
                dw(:, k, 3) = aimag(cv)
            end do
            s%nsit = s%nsit + 1
            w = w + dw
            call transform(s%cf%t, w, zs)
            del = sqrt((sum((dw(:, :, 1)/scs)**2) + sum((dw(:, :, 2)/scs)**2) + &
                        sum((dw(:, :, 3)/scs)**2))/(3*size(scs)))
            if (.not. ieee_is_finite(del)) exit
            if (del <= tol) then
                conv = .true.
                exit
            end if
            if (m > 1 .and. del > 0.5_dp*delp) exit
            delp = del
        end do
        if (.not. conv) call direct()
    contains
        !> y(:, :, i) = sum_j m(i, j) x(:, :, j)
        pure subroutine transform(mt, x, y)
            real(dp), intent(in) :: mt(3, 3), x(:, :, :)
            real(dp), intent(out) :: y(:, :, :)
            integer :: ii
            do ii = 1, 3
                y(:, :, ii) = mt(ii, 1)*x(:, :, 1) + mt(ii, 2)*x(:, :, 2) + mt(ii, 3)*x(:, :, 3)
            end do
        end subroutine transform
        !> The collocation equations of the sensitivities as one 3n x 3n system:
        !! zs_i - h sum_j a_ij J_j zs_j = h sum_j a_ij (J_j s0 + p_j).
        subroutine direct()
            real(dp) :: mm(3*s%n, 3*s%n), rhs(3*s%n, s%ns), g(s%n, s%ns, 3)
            integer :: ipv(3*s%n), ii, jj, n
            type(status_t) :: lst
            n = s%n
            s%nsdir = s%nsdir + 1
            mm = 0.0_dp
            do jj = 1, 3
                g(:, :, jj) = matmul(jm(:, :, jj), s%sy) + pk(:, :, jj)
            end do
            do ii = 1, 3
                rhs((ii - 1)*n + 1:ii*n, :) = s%h*(s%cf%a(ii, 1)*g(:, :, 1) + &
                    s%cf%a(ii, 2)*g(:, :, 2) + s%cf%a(ii, 3)*g(:, :, 3))
                do jj = 1, 3
                    mm((ii - 1)*n + 1:ii*n, (jj - 1)*n + 1:jj*n) = -s%h*s%cf%a(ii, jj)*jm(:, :, jj)
                end do
            end do
            do ii = 1, 3*n
                mm(ii, ii) = mm(ii, ii) + 1.0_dp
            end do
            call la_lu_factor(mm, ipv, lst)
            if (lst%code /= STATUS_OK) then
                call set_error(stat, RADAU_ERR_SINGULAR, 'radau: the sensitivities'' '// &
                    'collocation system is singular')
                call s%prefix_time(stat, s%t)
                return
            end if
            do k = 1, s%ns
                call la_lu_solve(mm, ipv, rhs(:, k), stat)
                if (stat%code /= STATUS_OK) return
            end do
            do ii = 1, 3
                zs(:, :, ii) = rhs((ii - 1)*n + 1:ii*n, :)
            end do
        end subroutine direct
    end subroutine sens_stages

    !> The sensitivities' error estimate, by the state's embedded formula and filter
    !! (estimate), in their own weights.
    real(dp) function sens_error(s, zs) result(err)
        type(radau_t), intent(in) :: s
        real(dp), intent(in) :: zs(:, :, :)
        real(dp) :: v(s%n), scs(s%n)
        type(status_t) :: st
        integer :: k
        err = 1.0e-10_dp
        do k = 1, s%ns
            v = s%sf0(:, k) + (s%cf%e(1)*zs(:, k, 1) + s%cf%e(2)*zs(:, k, 2) + &
                               s%cf%e(3)*zs(:, k, 3))/(s%h*s%cf%gam0)
            call la_lu_solve(s%e1, s%ip1, v, st)
            if (st%code /= STATUS_OK) then
                err = huge(1.0_dp)
                return
            end if
            scs = s%satol(:, k) + s%rtol*max(abs(s%sy(:, k)), abs(s%sy(:, k) + zs(:, k, 3)))
            err = max(err, rms(v/scs))
        end do
        if (.not. ieee_is_finite(err)) err = huge(1.0_dp)
    end function sens_error

    !> Factor gam/h I - J (real) and (alpha + i beta)/h I - J (complex) for the current h.
    subroutine factor(s, stat)
        type(radau_t), intent(inout) :: s
        type(status_t), intent(out) :: stat
        real(dp) :: fac1
        complex(dp) :: fac2
        integer :: i
        fac1 = s%cf%gam/s%h
        fac2 = cmplx(s%cf%alpha, s%cf%beta, kind=dp)/s%h
        s%e1 = -s%jac
        s%e2 = cmplx(-s%jac, 0.0_dp, kind=dp)
        do i = 1, s%n
            s%e1(i, i) = s%e1(i, i) + fac1
            s%e2(i, i) = s%e2(i, i) + fac2
        end do
        s%nlu = s%nlu + 1
        s%h_lu = s%h
        s%need_lu = .false.
        call la_lu_factor(s%e1, s%ip1, stat)
        if (stat%code == STATUS_OK) call la_zlu_factor(s%e2, s%ip2, stat)
        if (stat%code /= STATUS_OK) then
            s%need_lu = .true.
            s%h_lu = 0.0_dp
        end if
    end subroutine factor

    !> Starting values of the stage increments: zero on the first step and after a
    !! rejection, else the previous step's collocation polynomial at the new nodes.
    subroutine starting_values(s, z)
        type(radau_t), intent(in) :: s
        real(dp), intent(out) :: z(:, :)
        real(dp) :: sn, l(3)
        integer :: i, j
        z = 0.0_dp
        if (s%first .or. s%rejected .or. .not. s%have_step) return
        do i = 1, 3
            sn = 1.0_dp + s%cf%c(i)*s%h/s%hu
            l = lagrange(s%cf, sn)
            do j = 1, 3
                z(:, i) = z(:, i) + l(j)*s%z_old(:, j)
            end do
            z(:, i) = z(:, i) - s%z_old(:, 3)
        end do
    end subroutine starting_values

    !> The simplified Newton iteration for the stage increments z (in: starting values;
    !! out: the solution).  conv: converged; else hnew is the step to try next.  newt:
    !! iterations used.  The iteration runs on W = T^-1 Z (see the header).
    subroutine newton(s, sys, z, sc, conv, newt, hnew, stat)
        type(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(inout) :: z(:, :)
        real(dp), intent(in) :: sc(:)
        logical, intent(out) :: conv
        integer, intent(out) :: newt
        real(dp), intent(out) :: hnew
        type(status_t), intent(out) :: stat
        real(dp) :: w(s%n, 3), f(s%n, 3), r(s%n, 3), dw(s%n, 3), fac1, alphn, betan
        real(dp) :: dyno, dyno_old, thq, thq_old, predicted
        complex(dp) :: cv(s%n)
        integer :: i
        stat%code = STATUS_OK
        conv = .false.
        hnew = 0.5_dp*s%h
        fac1 = s%cf%gam/s%h
        alphn = s%cf%alpha/s%h
        betan = s%cf%beta/s%h
        w = matmul(z, transpose(s%cf%tinv))          ! w(:, i) = sum_j tinv(i, j) z(:, j)
        s%eta = max(s%eta, UROUND)**0.8_dp
        s%theta = 0.0_dp
        dyno_old = 0.0_dp
        thq_old = 0.0_dp
        newt = 0
        do
            if (newt >= NEWTON_MAX) return
            do i = 1, 3
                call sys%rhs(s%t + s%cf%c(i)*s%h, s%y + z(:, i), f(:, i), stat)
                if (stat%code /= STATUS_OK) then
                    call s%prefix_time(stat, s%t)
                    return
                end if
            end do
            s%nfe = s%nfe + 3
            newt = newt + 1
            s%nit = s%nit + 1
            if (.not. all(ieee_is_finite(f))) return         ! a smaller step
            r = matmul(f, transpose(s%cf%tinv))
            r(:, 1) = r(:, 1) - fac1*w(:, 1)
            r(:, 2) = r(:, 2) - (alphn*w(:, 2) - betan*w(:, 3))
            r(:, 3) = r(:, 3) - (betan*w(:, 2) + alphn*w(:, 3))
            dw(:, 1) = r(:, 1)
            call la_lu_solve(s%e1, s%ip1, dw(:, 1), stat)
            if (stat%code /= STATUS_OK) return
            cv = cmplx(r(:, 2), r(:, 3), kind=dp)
            call la_zlu_solve(s%e2, s%ip2, cv, stat)
            if (stat%code /= STATUS_OK) return
            dw(:, 2) = real(cv)
            dw(:, 3) = aimag(cv)
            dyno = sqrt((rms(dw(:, 1)/sc)**2 + &
                         rms(dw(:, 2)/sc)**2 + &
                         rms(dw(:, 3)/sc)**2)/3.0_dp)
            if (.not. ieee_is_finite(dyno)) return
            if (newt > 1) then
                thq = dyno/dyno_old
                if (newt == 2) then
                    s%theta = thq
                else
                    s%theta = sqrt(thq*thq_old)
                end if
                thq_old = thq
                if (s%theta >= 0.99_dp) return             ! diverging: halve h
                s%eta = s%theta/(1.0_dp - s%theta)
                predicted = s%eta*dyno*s%theta**(NEWTON_MAX - newt)
                if (predicted > s%fnewt) then
                    ! would not converge within NEWTON_MAX: a step that should
                    hnew = s%h*max(0.2_dp, min(0.5_dp, &
                        0.8_dp*(s%fnewt/predicted)**(1.0_dp/real(4 + NEWTON_MAX - newt, dp))))
                    return
                end if
            end if
            dyno_old = max(dyno, UROUND)
            w = w + dw
            z = matmul(w, transpose(s%cf%t))
            if (s%eta*dyno <= s%fnewt) exit
        end do
        conv = .true.
    end subroutine newton

    !> The filtered error estimate err = (I - h gam0 J)^-1 (gam0 h f0 + sum e_i z_i) and its
    !! norm; on the first step and after a rejection an estimate >= 1 is filtered once more
    !! through f(t, y + err) (Hairer & Wanner IV.8).
    subroutine estimate(s, sys, z, sc, err, stat)
        type(radau_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: z(:, :), sc(:)
        real(dp), intent(out) :: err
        type(status_t), intent(out) :: stat
        real(dp) :: v(s%n), g(s%n), ez(s%n), fe(s%n)
        err = huge(1.0_dp)
        ! (I - h gam0 J) = h gam0 (gam/h I - J): divide the right-hand side by h gam0
        ez = (s%cf%e(1)*z(:, 1) + s%cf%e(2)*z(:, 2) + s%cf%e(3)*z(:, 3))/(s%h*s%cf%gam0)
        g = s%f0 + ez
        v = g
        call la_lu_solve(s%e1, s%ip1, v, stat)
        if (stat%code /= STATUS_OK) return
        err = max(rms(v/sc), 1.0e-10_dp)
        if (err >= 1.0_dp .and. (s%first .or. s%rejected)) then
            call sys%rhs(s%t, s%y + v, fe, stat)
            s%nfe = s%nfe + 1
            if (stat%code /= STATUS_OK) then
                call s%prefix_time(stat, s%t)
                return
            end if
            v = fe + ez
            call la_lu_solve(s%e1, s%ip1, v, stat)
            if (stat%code /= STATUS_OK) return
            err = max(rms(v/sc), 1.0e-10_dp)
        end if
        if (.not. ieee_is_finite(err)) err = huge(1.0_dp)
    end subroutine estimate

    ! ------------------------------------------------------------------------------------
    ! Dense output
    ! ------------------------------------------------------------------------------------

    !> Values L_j(x) of the collocation basis: L_j(x) = x prod_{m /= j} (x - c_m) lag_j,
    !! L_j(0) = 0, L_j(c_i) = delta_ij.
    pure function lagrange(cf, x) result(l)
        type(radau_coeffs_t), intent(in) :: cf
        real(dp), intent(in) :: x
        real(dp) :: l(3)
        l(1) = x*(x - cf%c(2))*(x - cf%c(3))*cf%lag(1)
        l(2) = x*(x - cf%c(1))*(x - cf%c(3))*cf%lag(2)
        l(3) = x*(x - cf%c(1))*(x - cf%c(2))*cf%lag(3)
    end function lagrange

    !> Derivatives dL_j/dx of the collocation basis.
    pure function lagrange_d(cf, x) result(l)
        type(radau_coeffs_t), intent(in) :: cf
        real(dp), intent(in) :: x
        real(dp) :: l(3)
        l(1) = ((x - cf%c(2))*(x - cf%c(3)) + x*(x - cf%c(3)) + x*(x - cf%c(2)))*cf%lag(1)
        l(2) = ((x - cf%c(1))*(x - cf%c(3)) + x*(x - cf%c(3)) + x*(x - cf%c(1)))*cf%lag(2)
        l(3) = ((x - cf%c(1))*(x - cf%c(2)) + x*(x - cf%c(2)) + x*(x - cf%c(1)))*cf%lag(3)
    end function lagrange_d

    !> The collocation polynomial of the last step at x (dense_position), k = 0, or its
    !! derivative, k = 1, for m values at once (the state's, or the sensitivities' n ns):
    !! v_old + sum_j L_j(x) z_j, or sum_j L_j'(x) z_j/hu; before the first step the values
    !! at t (k = 0) or their slope (k = 1).
    pure subroutine collocation(s, x, k, m, v_now, f_now, v_old, z, v)
        type(radau_t), intent(in) :: s
        real(dp), intent(in) :: x                   !! (t - t_old)/hu
        integer, intent(in) :: k, m                 !! derivative (0 or 1), values
        real(dp), intent(in) :: v_now(m), f_now(m)  !! the values at t and their slope
        real(dp), intent(in) :: v_old(m)            !! the values at the last step's start
        real(dp), intent(in) :: z(m, 3)             !! its stage increments
        real(dp), intent(inout) :: v(m)             !! 0 on entry; the result
        real(dp) :: l(3)
        integer :: j
        if (.not. s%have_step) then
            if (k == 0) v = v_now
            if (k == 1) v = f_now
            return
        end if
        if (k == 0) then
            l = lagrange(s%cf, x)
            v = v_old
        else
            l = lagrange_d(s%cf, x)/s%hu
        end if
        do j = 1, 3
            v = v + l(j)*z(:, j)
        end do
    end subroutine collocation

    !> Where t lies in the last step, x = (t - t_old)/hu (0 before the first step, where
    !! only t = t0 is allowed), and the checks of dense output (k = 0 or 1, t in the step).
    subroutine dense_position(s, t, k, what, x, stat)
        type(radau_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        character(len=*), intent(in) :: what        !! the procedure asked: 'dense', ...
        real(dp), intent(out) :: x
        type(status_t), intent(out) :: stat
        stat%code = STATUS_OK
        x = 0.0_dp
        if (k < 0 .or. k > 1) then
            call set_error(stat, RADAU_ERR_ILLEGAL_INPUT, 'radau '//what//': k must be 0 or 1')
            return
        end if
        call s%check_in_step(t, what, stat)
        if (stat%code /= STATUS_OK .or. .not. s%have_step) return
        x = (t - s%t_old)/s%hu
    end subroutine dense_position

    ! ------------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------------

    pure real(dp) function rms(v)
        real(dp), intent(in) :: v(:)
        rms = sqrt(sum(v**2)/size(v))
    end function rms

end module radau
