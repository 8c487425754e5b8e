!> The estimator: nonlinear least squares for every fit of the program (the inversion of
!! periods, the fit of a record, the tensor's fit, and any fit to come).  One algorithm,
!! one set of convergence tests, one covariance.
!!
!! Minimise S(p) = ||r(p)||^2 over n parameters p for m >= n residuals r, each already
!! divided by its standard uncertainty (so S is chi^2).  A problem extends lsq_problem_t and
!! gives r(p) (residual); it may give its own Jacobian with the residuals at every point
!! (has_jacobian, residual_jacobian: e.g. forward sensitivities) or at a point whose
!! residuals it has just given (jacobian: e.g. differences with a step of its own); else
!! J is taken by forward differences with the steps of the options.  A failed evaluation
!! (a model that leaves its range) returns a status and is a rejected step, unless the
!! options say it ends the fit.  Written here from the published descriptions:
!!
!! * Gauss-Newton with Levenberg-Marquardt damping (K. Levenberg, Q. Appl. Math. 2, 1944;
!!   D. W. Marquardt, J. SIAM 11, 1963): the step minimises ||J d + r||^2 + lambda ||D d||^2.
!!   Two dampings (options%damping):
!!   - DAMP_MARQUARDT: D_j the largest column norm of J seen so far (J. J. Moré, Lecture
!!     Notes in Math. 630, 1978: the method is then invariant to the parameters' units), the
!!     step the least-squares solution of the stacked matrix [J; sqrt(lambda) D] (J^T J
!!     never formed): J = Q R by Householder reflections once at each point with a
!!     Jacobian (the Gauss-Newton step's too; a Jacobian taken again keeps its factors),
!!     each damped step from the 2n x n problem [R; sqrt(lambda) D] d = [-Q^T r; 0] (the
!!     same minimum: Q^T is orthogonal), accepted when the gain ratio
!!     rho = (S(p) - S(p + d)) / (S(p) - ||J d + r||^2) of the actual to the predicted
!!     reduction is positive; lambda then times max(1/3, 1 - (2 rho - 1)^3), nu = 2, and on
!!     a rejection times nu, nu doubled (H. B. Nielsen, IMM-REP-1999-05, DTU; K. Madsen,
!!     H. B. Nielsen & O. Tingleff, "Methods for non-linear least squares problems", 2004).
!!   - DAMP_HALVING: D^T D = J^T J, the metric of the Gauss-Newton step itself: the damped
!!     step is the Gauss-Newton step over 1 + lambda, which each rejection doubles (the
!!     step halved along the Gauss-Newton direction; lambda 0 again at each new point).  A
!!     step is accepted when S(p + d) <= S(p) (1 + rise).  For fits whose Gauss-Newton
!!     steps are good from the start and whose domain is kept by shortening them.
!!   A step outside the domain (options lower, upper: strict bounds) is rejected without
!!   an evaluation.  DAMP_HALVING refuses a Jacobian whose columns, scaled to unit norm,
!!   have a condition number beyond 1e14 (its undamped step has no digit left), naming the
!!   parameters it cannot separate.
!! * Convergence (each test off with a tolerance of 0):
!!   - the gradient test: the gain g the undamped (Gauss-Newton) step of the current
!!     Jacobian could still make, g = (S - min ||J d + r||^2) (m - n) / S, the fall of
!!     chi^2 measured in the residuals' own variance s^2 = S / (m - n), i.e. the square of
!!     the remaining step in standard errors: converged when g <= gtol (at the start and at
!!     each new Jacobian);
!!   - the orthogonality test: the cosine of the angle between r and the range of J,
!!     ((S - min ||J d + r||^2) / S)^(1/2) <= otol (MINPACK's gtol; for one parameter
!!     |J . r| / (|J| |r|));
!!   - the step test, after an accepted step d from p: |d| <= xtol (|p| + xtol) in Moré's
!!     scaled norm ||D .|| (STEP_SCALED, p before the step) or max_j |d_j| <= xtol max_j |p_j|
!!     (STEP_LARGEST, p after the step: parameters of one kind and size, e.g. a tensor's
!!     entries); or the reduction test: S fell by at most ftol S and the linear model
!!     predicted at most that.  Such a small step is convergence while g <= small_gain
!!     (a small step with much still to gain is what a fit pressed against parameters the
!!     model cannot take looks like); with small_gain = huge it is convergence at once,
!!     without a new Jacobian;
!!   - an exact fit: S = 0, or S below `exact` (1e-20) of its start (roundoff);
!!   - convergence at roundoff: when no step along the damping's path lowers S any more
!!     (lambda beyond lambda_max), the fit has reached the floor set by the noise of its
!!     residuals and Jacobian; that is success when g <= floor_gain, or the last accepted
!!     step was small, or the fit is exact or orthogonal, or the undamped step passes the
!!     step test with floor_xtol.  Failure (ERR_NUMERIC): max_iter steps tried or
!!     max_jacobians Jacobians, or the floor above all of those.
!! * Robust loss (loss = LOSS_HUBER): iteratively reweighted least squares (P. J. Huber,
!!   Ann. Math. Stat. 35, 1964): after the fit, each residual gets the weight
!!   min(1, c s / |r_i|) (c = huber_c, 1.345: 95 % efficiency at normal errors;
!!   s = 1.4826 median |r_i|, the robust scale, from the residuals without weights), the
!!   residuals and the rows of J are multiplied by the weights' roots, and the fit is
!!   repeated from its estimate, reweightings times.
!! * The gain g is computed once at each point that has a Jacobian (with a problem's own
!!   Jacobian: every point tried) and told the problem (note_gain; the record fit's
!!   evaluator decides from it what its next run carries).
!! * Counts: iterations (steps tried, accepted or not), jacobians (the start's and one at
!!   each accepted point that the step test did not end), evaluations (of the residuals;
!!   a difference Jacobian counts its own).
!! * The result: p, r, J (the last Jacobian: at p, but after a final step that the step
!!   test ended alone, at the point before it), chi^2 = S, dof = m - n, the Birge ratio
!!   (chi^2/dof)^(1/2), and with options%covariance the p-value of chi^2 (module stats) and
!!   the covariance (J^T J)^-1 with its form scaled by s^2 = chi^2/dof for residuals whose
!!   u are not stated (lsq_covariance: singular values of J with its columns scaled to unit
!!   norm); for a rank-deficient J, which parameters the data cannot tell apart (named
!!   from options%names).
!! * The self-check (with options%covariance): when the residuals are divided by stated u
!!   (options%u_stated), chi^2 with dof tests them: p < consistency_level (0.05) marks the
!!   fit inconsistent and inflates its covariance by the Birge ratio squared (cov_fit), so
!!   that no u is below what the residuals imply (R. T. Birge, Phys. Rev. 40, 1932); the
!!   residual with the largest normalised size is named (worst) for the caller's warning.
!!   With u from the scatter, cov_fit is cov_scaled.
!!
!! No routine stops; failures come back in status_t.
module estimator
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC
    use lapack_wrap, only: la_svd
    use text, only: itoa, sci
    use stats, only: chi2_sf
    use unused_arg, only: unused
    implicit none
    private

    !> The dampings (options%damping), the step tests' norms (options%step_norm), the losses
    !! (options%loss).
    integer, parameter, public :: DAMP_MARQUARDT = 1, DAMP_HALVING = 2
    integer, parameter, public :: STEP_SCALED = 1, STEP_LARGEST = 2
    integer, parameter, public :: LOSS_SQUARES = 1, LOSS_HUBER = 2

    !> How a fit ended (result%ended): converged by a test, or failed.
    integer, parameter, public :: CONV_GRADIENT = 1, CONV_ORTHOGONAL = 2, CONV_STEP = 3, &
        CONV_EXACT = 4, CONV_FLOOR = 5
    integer, parameter, public :: FAIL_ITERATIONS = -1, FAIL_FLOOR = -2, FAIL_START = -3, &
        FAIL_EVALUATION = -4, FAIL_JACOBIAN = -5, FAIL_STEP = -6

    !> A least-squares problem: residuals r(p) (nres of them, each divided by its standard
    !! uncertainty) of n parameters.
    type, abstract, public :: lsq_problem_t
    contains
        procedure(residual_i), deferred :: residual
        procedure(nres_i), deferred :: nres
        procedure :: has_jacobian => no_jacobian_given
        procedure :: residual_jacobian => no_residual_jacobian
        procedure :: jacobian => difference_jacobian
        procedure :: note_gain => ignore_gain
    end type lsq_problem_t

    !> A Householder QR factorisation J = Q R of an m x n matrix (m >= n), and Q^T b of a
    !! right-hand side: the reflectors' vectors below the diagonal of a (their first element
    !! 1, not stored), R on and above it, the reflectors' factors tau (H_k = I - tau_k v_k
    !! v_k^T); qtb the first n elements of Q^T b.
    type :: qr_t
        real(dp), allocatable :: a(:, :), tau(:), qtb(:)
    end type qr_t

    abstract interface
        !> r(p); stat /= 0 when p cannot be evaluated (a step there is rejected).
        subroutine residual_i(prob, p, r, stat)
            import :: lsq_problem_t, dp, status_t
            class(lsq_problem_t), intent(inout) :: prob
            real(dp), intent(in) :: p(:)
            real(dp), intent(out) :: r(:)
            type(status_t), intent(out) :: stat
        end subroutine residual_i
        !> The number of residuals.
        integer function nres_i(prob)
            import :: lsq_problem_t
            class(lsq_problem_t), intent(in) :: prob
        end function nres_i
    end interface

    !> Options of estimate (the defaults: Levenberg-Marquardt with the tolerances of a
    !! record fit).
    type, public :: lsq_options_t
        integer :: damping = DAMP_MARQUARDT
        real(dp) :: lambda0 = 1.0e-3_dp         !! first lambda (DAMP_MARQUARDT)
        !> lambda beyond which no step lowers S: the floor (DAMP_HALVING: 2^k - 1 after k
        !! halvings)
        real(dp) :: lambda_max = 1.0e16_dp
        real(dp) :: rise = 0.0_dp               !! DAMP_HALVING: accepted S(p + d) <= S (1 + rise)
        integer :: max_iter = 60                !! most steps tried (accepted or not)
        integer :: max_jacobians = huge(1)      !! most Jacobians (linearisations)
        real(dp) :: gtol = 1.0e-4_dp            !! gradient test: the gain g left (chi^2 units)
        real(dp) :: otol = 0.0_dp               !! orthogonality test: cos(r, range J)
        real(dp) :: xtol = 1.0e-9_dp            !! step test
        integer :: step_norm = STEP_SCALED      !! its norm
        real(dp) :: ftol = 1.0e-13_dp           !! reduction test
        real(dp) :: small_gain = 1.0_dp         !! a small step ends the fit while g <= this
        real(dp) :: floor_gain = 1.0_dp         !! at the floor: converged when g <= this
        real(dp) :: floor_xtol = 0.0_dp         !! at the floor: ... or the undamped step this small
        !> An exact fit: S fallen to this part of its start (roundoff; 0: only S = 0)
        real(dp) :: exact = 1.0e-20_dp
        !> A failed evaluation at a trial point ends the fit (else it is a rejected step)
        logical :: fail_on_error = .false.
        real(dp), allocatable :: lower(:), upper(:) !! the domain: lower < p < upper
        real(dp), allocatable :: h(:)           !! difference steps (default 1e-7 max(|p0_j|, 1))
        integer :: loss = LOSS_SQUARES
        integer :: reweightings = 3             !! LOSS_HUBER: refits with new weights
        real(dp) :: huber_c = 1.345_dp          !! LOSS_HUBER: c, in robust standard deviations
        logical :: covariance = .false.         !! compute the covariance and the p-value
        !> The residuals are divided by stated standard uncertainties, so chi^2 tests them
        !! (the self-check below); .false.: the scatter sets u (cov_scaled is the covariance)
        logical :: u_stated = .true.
        real(dp) :: consistency_level = 0.05_dp !! p below this: the residuals exceed their u
        character(len=16), allocatable :: names(:)  !! the parameters' names, for messages
    end type lsq_options_t

    !> What estimate found.
    type, public :: lsq_result_t
        real(dp), allocatable :: p(:)           !! parameters (the last accepted)
        real(dp), allocatable :: r(:)           !! residuals there (times the robust roots)
        real(dp), allocatable :: jac(:, :)      !! the last Jacobian (see the module header)
        real(dp), allocatable :: robust(:)      !! LOSS_HUBER: the robust weights' roots
        real(dp) :: cost = 0.0_dp               !! S = ||r||^2 = chi^2
        real(dp) :: gain = huge(1.0_dp)         !! g at the last Jacobian
        integer :: dof = 0                      !! m - n
        real(dp) :: birge = 0.0_dp              !! (chi^2 / dof)^(1/2) (dof >= 1)
        real(dp) :: p_value = 1.0_dp            !! P(chi^2_dof > chi^2) (options%covariance)
        !> (J^T J)^-1 and s^2 (J^T J)^-1, s^2 = chi^2/dof (options%covariance; allocated
        !! when J has full rank, else `note` names the parameters the data cannot separate)
        real(dp), allocatable :: cov(:, :), cov_scaled(:, :)
        character(len=:), allocatable :: note
        !> The self-check (options%covariance): consistent is .false. when the u are stated
        !! and p_value < consistency_level; inflation = max(1, Birge ratio) then, else 1;
        !! cov_fit = cov inflation^2 (u stated) or cov_scaled (u from the scatter): the
        !! covariance to report, never below what the residuals imply.  worst: the residual
        !! with the largest |r_i| (in units of its u).
        logical :: consistent = .true.
        real(dp) :: inflation = 1.0_dp
        integer :: worst = 0
        real(dp), allocatable :: cov_fit(:, :)
        real(dp) :: lambda = 0.0_dp             !! the damping at the end
        integer :: iterations = 0               !! steps tried (accepted or not)
        integer :: jacobians = 0                !! Jacobians (the start's included)
        integer :: evaluations = 0              !! residual evaluations (Jacobians included)
        integer :: ended = 0                    !! CONV_* or FAIL_*
        logical :: converged = .false.
    end type lsq_result_t

    public :: estimate, lsq_jacobian, gauss_newton_gain, lsq_covariance

    !> Largest condition number of J with its columns scaled to unit norm: the covariance's,
    !! and an undamped step's (DAMP_HALVING; beyond it the step has no digit left).
    real(dp), parameter :: COND_MAX = 1.0e10_dp, STEP_COND_MAX = 1.0e14_dp

contains

    !> The fit from p0 (see the module header).  On failure res holds the last accepted
    !! point and stat says why (ERR_NUMERIC; or the failure of an evaluation, with res%ended
    !! FAIL_START, FAIL_EVALUATION or FAIL_JACOBIAN).
    subroutine estimate(prob, p0, opts, res, stat)
        class(lsq_problem_t), intent(inout) :: prob !! the residuals
        real(dp), intent(in) :: p0(:)           !! start
        type(lsq_options_t), intent(in) :: opts
        type(lsq_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        type(lsq_result_t) :: part
        real(dp), allocatable :: hw(:)
        logical :: ok
        integer :: k
        allocate (hw(prob%nres()))
        hw = 1.0_dp
        call solve(prob, p0, opts, hw, res, stat)
        if (opts%loss == LOSS_HUBER .and. stat%code == 0) then
            do k = 1, opts%reweightings
                call huber_roots(res%r/hw, opts%huber_c, hw, ok)
                if (.not. ok) exit
                call solve(prob, res%p, opts, hw, part, stat)
                part%iterations = part%iterations + res%iterations
                part%jacobians = part%jacobians + res%jacobians
                part%evaluations = part%evaluations + res%evaluations
                call move_result(part, res)
                if (stat%code /= 0) exit
            end do
        end if
        if (opts%loss == LOSS_HUBER) call move_alloc(hw, res%robust)
        if (stat%code == 0) call statistics(res, opts)
    end subroutine estimate

    !> chi^2, its degrees of freedom, the Birge ratio; with options%covariance the p-value
    !! and the covariance.
    subroutine statistics(res, opts)
        type(lsq_result_t), intent(inout) :: res
        type(lsq_options_t), intent(in) :: opts
        type(status_t) :: st
        real(dp), allocatable :: cov(:, :)
        if (.not. allocated(res%r) .or. .not. allocated(res%p)) return
        res%dof = size(res%r) - size(res%p)
        res%birge = 0.0_dp
        if (res%dof > 0) res%birge = sqrt(res%cost/res%dof)
        if (.not. opts%covariance) return
        res%p_value = 1.0_dp
        if (res%dof > 0) res%p_value = chi2_sf(res%cost, real(res%dof, dp))
        call lsq_covariance(res%jac, 1.0_dp, cov, st, opts%names)
        if (st%code /= 0) then
            res%note = st%msg
            return
        end if
        res%cov = cov
        res%cov_scaled = cov*(res%cost/max(1, res%dof))
        call self_check(res, opts)
    end subroutine statistics

    !> The fit checks itself against the u of its residuals (module header: the result).
    subroutine self_check(res, opts)
        type(lsq_result_t), intent(inout) :: res
        type(lsq_options_t), intent(in) :: opts
        res%worst = 0
        if (size(res%r) > 0) res%worst = maxloc(abs(res%r), 1)
        res%consistent = .true.
        res%inflation = 1.0_dp
        if (.not. opts%u_stated) then
            res%cov_fit = res%cov_scaled
            return
        end if
        if (res%dof > 0 .and. res%p_value < opts%consistency_level) then
            res%consistent = .false.
            res%inflation = max(1.0_dp, res%birge)
        end if
        res%cov_fit = res%cov*res%inflation**2
    end subroutine self_check

    !> res = part (the allocations moved).
    subroutine move_result(part, res)
        type(lsq_result_t), intent(inout) :: part
        type(lsq_result_t), intent(inout) :: res
        call move_alloc(part%p, res%p)
        call move_alloc(part%r, res%r)
        call move_alloc(part%jac, res%jac)
        res%cost = part%cost
        res%gain = part%gain
        res%lambda = part%lambda
        res%iterations = part%iterations
        res%jacobians = part%jacobians
        res%evaluations = part%evaluations
        res%ended = part%ended
        res%converged = part%converged
    end subroutine move_result

    !> One fit from p0 with the robust roots hw on the residuals (see the module header).
    subroutine solve(prob, p0, opts, hw, res, stat)
        class(lsq_problem_t), intent(inout) :: prob
        real(dp), intent(in) :: p0(:), hw(:)
        type(lsq_options_t), intent(in) :: opts
        type(lsq_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: ru(:), rt(:), rtu(:), jt(:, :), jd(:), h(:)
        type(qr_t) :: f, ft     ! the factors of res%jac and jt, with their residuals' -Q^T r
        real(dp) :: dvec(size(p0)), dstep(size(p0)), dgn(size(p0)), dgn_t(size(p0))
        real(dp) :: pt(size(p0)), lambda, nu, st, pred, rho, cost0, red, red_t, gain_t
        logical :: analytic, weighted, small, last_small, inside, accepted, halving, deficient
        logical :: same
        type(status_t) :: s2
        integer :: n, m, j, ne
        n = size(p0)
        m = size(hw)
        red_t = 0.0_dp
        gain_t = huge(1.0_dp)
        dgn_t = 0.0_dp
        halving = opts%damping == DAMP_HALVING
        weighted = any(hw /= 1.0_dp)
        allocate (res%p(n), res%r(m), res%jac(m, n), ru(m), rt(m), rtu(m), jd(m))
        if (allocated(opts%h)) then
            h = opts%h
        else
            h = 1.0e-7_dp*max(abs(p0), 1.0_dp)
        end if
        res%p = p0
        analytic = prob%has_jacobian()
        ! the start
        res%evaluations = 1
        res%jacobians = 1
        if (analytic) then
            allocate (jt(m, n))
            call prob%residual_jacobian(res%p, ru, res%jac, stat)
            if (stat%code /= 0) then
                res%ended = FAIL_START
                return
            end if
            call weigh(ru, res%r, res%jac)
            call linearise_qr(res%r, res%jac, f, .true., dgn, red, res%gain)
            call prob%note_gain(res%gain)
        else
            call prob%residual(res%p, ru, stat)
            if (stat%code /= 0) then
                res%ended = FAIL_START
                return
            end if
            call weigh(ru, res%r)
            call new_jacobian()
            if (stat%code /= 0) return
        end if
        res%cost = sum(res%r**2)
        cost0 = res%cost
        dvec = 0.0_dp
        call scale_columns()
        if (converged_at_jacobian(.false.)) return
        lambda = 0.0_dp
        if (.not. halving) lambda = opts%lambda0
        res%lambda = lambda
        nu = 2.0_dp
        last_small = .false.
        do
            if (res%iterations >= opts%max_iter) then
                call not_converged(FAIL_ITERATIONS)
                return
            end if
            res%iterations = res%iterations + 1
            if (res%cost == 0.0_dp) then
                call ends(CONV_EXACT)
                return
            end if
            ! the step
            if (halving) then
                if (lambda == 0.0_dp) then
                    ! a new Jacobian: its Gauss-Newton step must have digits
                    deficient = .not. (res%gain < huge(1.0_dp))
                    if (.not. deficient) deficient = condition(res%jac) > STEP_COND_MAX
                    if (deficient) then
                        call set_error(stat, ERR_NUMERIC, 'the Gauss-Newton step: the '// &
                            'Jacobian is rank deficient: '//inseparable(res%jac, opts%names))
                        res%ended = FAIL_STEP
                        return
                    end if
                end if
                dstep = dgn*(1.0_dp/(1.0_dp + lambda))
            else
                ! min ||J d + r||^2 + lambda ||D d||^2 as one least-squares problem, through
                ! J = Q R: min ||R d - (-Q^T r)_1..n||^2 + lambda ||D d||^2 (2n rows)
                call damped_step(f, sqrt(lambda)*dvec, dstep, stat)
                if (stat%code /= 0) then
                    stat%msg = 'the step: '//stat%msg
                    res%ended = FAIL_STEP
                    return
                end if
            end if
            jd = matmul(res%jac, dstep)
            pred = res%cost - sum((res%r + jd)**2)
            pt = res%p + dstep
            inside = .true.
            if (allocated(opts%lower)) inside = all(pt > opts%lower)
            if (allocated(opts%upper)) inside = inside .and. all(pt < opts%upper)
            accepted = .false.
            rho = -1.0_dp
            st = huge(1.0_dp)
            if (inside) then
                if (analytic) then
                    call prob%residual_jacobian(pt, rtu, jt, s2)
                else
                    call prob%residual(pt, rtu, s2)
                end if
                res%evaluations = res%evaluations + 1
                if (s2%code /= 0 .and. opts%fail_on_error) then
                    stat = s2
                    res%ended = FAIL_EVALUATION
                    return
                end if
                if (s2%code == 0) then
                    if (analytic) then
                        call weigh(rtu, rt, jt)
                        ! the same Jacobian again (a problem's Jacobian taken again from an
                        ! earlier point): its factors too
                        same = all(jt == res%jac)
                        if (same) ft = f
                        call linearise_qr(rt, jt, ft, .not. same, dgn_t, red_t, gain_t)
                        call prob%note_gain(gain_t)
                    else
                        call weigh(rtu, rt)
                    end if
                    st = sum(rt**2)
                    if (halving) then
                        accepted = st <= res%cost*(1.0_dp + opts%rise)
                    else
                        if (pred > 0.0_dp) rho = (res%cost - st)/pred
                        accepted = rho > 0.0_dp
                    end if
                end if
            end if
            if (accepted) then
                small = step_small(dstep, res%p, pt, opts%xtol) .or. (opts%ftol > 0.0_dp .and. &
                    res%cost - st <= opts%ftol*res%cost .and. pred <= opts%ftol*res%cost)
                res%p = pt
                res%r = rt
                ru = rtu
                res%cost = st
                if (halving) then
                    lambda = 0.0_dp
                else
                    lambda = lambda*max(1.0_dp/3.0_dp, 1.0_dp - (2.0_dp*rho - 1.0_dp)**3)
                end if
                res%lambda = lambda
                nu = 2.0_dp
                if (small .and. opts%small_gain >= huge(1.0_dp)) then
                    call ends(CONV_STEP)
                    return
                end if
                if (res%jacobians >= opts%max_jacobians) then
                    call not_converged(FAIL_ITERATIONS)
                    return
                end if
                res%jacobians = res%jacobians + 1
                if (analytic) then
                    res%jac = jt
                    call move_alloc(ft%a, f%a)
                    call move_alloc(ft%tau, f%tau)
                    call move_alloc(ft%qtb, f%qtb)
                    dgn = dgn_t
                    red = red_t
                    res%gain = gain_t
                else
                    call new_jacobian()
                    if (stat%code /= 0) return
                end if
                call scale_columns()
                if (converged_at_jacobian(small)) return
                last_small = small
            else
                if (halving) then
                    lambda = 2.0_dp*lambda + 1.0_dp
                else
                    lambda = lambda*nu
                    nu = 2.0_dp*nu
                end if
                if (lambda > opts%lambda_max) then
                    ! no step along the damping's path lowers S: a minimum to the residuals'
                    ! roundoff when the fit has (nearly) nothing left to gain
                    if (res%gain <= opts%floor_gain .or. last_small .or. &
                        res%cost <= opts%exact*cost0 .or. orthogonal() .or. &
                        (opts%floor_xtol > 0.0_dp .and. &
                         step_small(dgn, res%p, res%p, opts%floor_xtol))) then
                        call ends(CONV_FLOOR)
                    else
                        call not_converged(FAIL_FLOOR)
                    end if
                    return
                end if
            end if
        end do
    contains
        !> The residuals (and rows of J) times the robust roots.
        subroutine weigh(r_in, r_out, jac)
            real(dp), intent(in) :: r_in(:)
            real(dp), intent(out) :: r_out(:)
            real(dp), intent(inout), optional :: jac(:, :)
            integer :: jj
            if (.not. weighted) then
                r_out = r_in
                return
            end if
            r_out = r_in*hw
            if (present(jac)) then
                do jj = 1, size(jac, 2)
                    jac(:, jj) = jac(:, jj)*hw
                end do
            end if
        end subroutine weigh
        !> The problem's Jacobian at res%p (whose residuals are ru), weighed, its
        !! Gauss-Newton step and gain.
        subroutine new_jacobian()
            call prob%jacobian(res%p, ru, h, res%jac, ne, stat)
            res%evaluations = res%evaluations + ne
            if (stat%code /= 0) then
                res%ended = FAIL_JACOBIAN
                return
            end if
            if (weighted) then
                do j = 1, n
                    res%jac(:, j) = res%jac(:, j)*hw
                end do
            end if
            call linearise_qr(res%r, res%jac, f, .true., dgn, red, res%gain)
            call prob%note_gain(res%gain)
        end subroutine new_jacobian
        !> Moré's scaling: D_j = the largest column norm of J seen so far (never 0); the
        !! damping's (DAMP_MARQUARDT) and the scaled step test's.
        subroutine scale_columns()
            integer :: jj
            if (halving .and. opts%step_norm /= STEP_SCALED) return
            do jj = 1, n
                dvec(jj) = max(dvec(jj), norm2(res%jac(:, jj)))
                if (.not. (dvec(jj) > 0.0_dp)) dvec(jj) = 1.0_dp
            end do
        end subroutine scale_columns
        !> The tests at a new Jacobian (small: the step to it was small).
        logical function converged_at_jacobian(small_step) result(done)
            logical, intent(in) :: small_step
            done = .true.
            if (res%cost == 0.0_dp .or. res%cost <= opts%exact*cost0 .and. res%jacobians > 1) then
                call ends(CONV_EXACT)
            else if (opts%gtol > 0.0_dp .and. res%gain <= opts%gtol) then
                call ends(CONV_GRADIENT)
            else if (small_step .and. res%gain <= opts%small_gain) then
                call ends(CONV_STEP)
            else if (orthogonal()) then
                call ends(CONV_ORTHOGONAL)
            else
                done = .false.
            end if
        end function converged_at_jacobian
        !> The orthogonality test at the current point.
        logical function orthogonal()
            orthogonal = opts%otol > 0.0_dp .and. res%cost > 0.0_dp .and. &
                         red <= opts%otol**2*res%cost
        end function orthogonal
        !> Is step d from p (to pn) small by the step test with tolerance tol?
        logical function step_small(d, p, pn, tol)
            real(dp), intent(in) :: d(:), p(:), pn(:), tol
            if (opts%step_norm == STEP_LARGEST) then
                step_small = maxval(abs(d)) <= tol*maxval(abs(pn))
            else
                step_small = norm2(dvec*d) <= tol*(norm2(dvec*p) + tol)
            end if
        end function step_small
        subroutine ends(how)
            integer, intent(in) :: how
            res%ended = how
            res%converged = .true.
            stat%code = 0
        end subroutine ends
        !> ERR_NUMERIC: no convergence within the limits, or at a floor with much left to
        !! gain (or a rank-deficient J: the parameters the data cannot separate named).
        subroutine not_converged(how)
            integer, intent(in) :: how
            character(len=:), allocatable :: why
            res%ended = how
            if (how == FAIL_ITERATIONS .and. res%jacobians >= opts%max_jacobians) then
                why = 'the fit did not converge in '//itoa(res%jacobians)//' Jacobians'
            else
                why = 'the fit did not converge in '//itoa(res%iterations)//' steps'
            end if
            if (res%gain < huge(1.0_dp)) then
                call set_error(stat, ERR_NUMERIC, why//' (lambda = '//sci(lambda, 1)//'; the '// &
                    'Gauss-Newton step would still lower chi^2 by '//sci(res%gain, 1)//')')
            else
                call set_error(stat, ERR_NUMERIC, why//' (lambda = '//sci(lambda, 1)//'; the '// &
                    'Jacobian is rank deficient: '//inseparable(res%jac, opts%names)//')')
            end if
        end subroutine not_converged
    end subroutine solve

    !> The Gauss-Newton step dgn of (r, jac), the fall of S it promises (red) and the gain
    !! g = red (m - n) / S (0 at S = 0; huge, red 0 and dgn 0 when the step cannot be had:
    !! jac rank deficient).  One parameter: the closed form.
    subroutine linearise(r, jac, dgn, red, gain)
        real(dp), intent(in) :: r(:), jac(:, :)
        real(dp), intent(out) :: dgn(:), red, gain
        type(qr_t) :: f
        call linearise_qr(r, jac, f, .true., dgn, red, gain)
    end subroutine linearise

    !> linearise, with the factors of jac (f, with -Q^T r): computed when `factor`, else
    !! f already holds jac's (the same matrix) and only -Q^T r is formed.  The damped steps
    !! at this point solve with f (damped_step).
    subroutine linearise_qr(r, jac, f, factor, dgn, red, gain)
        real(dp), intent(in) :: r(:), jac(:, :)
        type(qr_t), intent(inout) :: f
        logical, intent(in) :: factor
        real(dp), intent(out) :: dgn(:), red, gain
        real(dp) :: cost, jj
        real(dp), allocatable :: qr(:)
        integer :: n, k
        gain = huge(1.0_dp)
        red = 0.0_dp
        dgn = 0.0_dp
        cost = sum(r**2)
        n = size(jac, 2)
        if (factor) then
            f%a = jac
            if (allocated(f%tau)) deallocate (f%tau)
            allocate (f%tau(n))
            call householder(f%a, f%tau)
        end if
        qr = -r
        call apply_qt(f%a, f%tau, qr)
        f%qtb = qr(1:n)
        if (n == 1) then
            jj = sum(jac(:, 1)**2)
            if (.not. (jj > 0.0_dp)) return
            dgn(1) = -sum(jac(:, 1)*r)/jj
            red = sum(jac(:, 1)*r)**2/jj
        else
            if (any([(f%a(k, k) == 0.0_dp, k=1, n)])) return
            dgn = f%qtb
            call back_substitute(f%a, dgn)
            red = cost - sum((r + matmul(jac, dgn))**2)
            if (.not. (red >= -1.0e-8_dp*cost) .or. .not. all(abs(dgn) < huge(1.0_dp))) then
                ! a reduction below 0 beyond roundoff: the step of a rank-deficient J
                dgn = 0.0_dp
                red = 0.0_dp
                return
            end if
        end if
        if (cost > 0.0_dp) then
            gain = red*max(1, size(r) - size(jac, 2))/cost
        else
            gain = 0.0_dp
        end if
    end subroutine linearise_qr

    !> The damped step: min ||J d + r||^2 + ||diag(dl) d||^2 from J = Q R (f, with -Q^T r
    !! of these residuals): the 2n x n problem [R; diag(dl)] d = [-Q^T r; 0] by its own QR.
    !! ERR_NUMERIC when that is rank deficient.
    subroutine damped_step(f, dl, d, stat)
        type(qr_t), intent(in) :: f
        real(dp), intent(in) :: dl(:)
        real(dp), intent(out) :: d(:)
        type(status_t), intent(out) :: stat
        real(dp) :: a(2*size(dl), size(dl)), b(2*size(dl)), tau(size(dl))
        integer :: n, j
        n = size(dl)
        d = 0.0_dp
        a = 0.0_dp
        do j = 1, n
            a(1:j, j) = f%a(1:j, j)
            a(n + j, j) = dl(j)
        end do
        b(1:n) = f%qtb
        b(n + 1:) = 0.0_dp
        call householder(a, tau)
        if (any([(a(j, j) == 0.0_dp, j=1, n)])) then
            call set_error(stat, ERR_NUMERIC, 'the damped least-squares matrix is not of '// &
                           'full rank')
            return
        end if
        call apply_qt(a, tau, b)
        d = b(1:n)
        call back_substitute(a, d)
    end subroutine damped_step

    !> Householder's QR of a (m x n, m >= n) in place: R on and above the diagonal, the
    !! reflectors' vectors below it (first element 1), their factors tau (0: no reflection).
    pure subroutine householder(a, tau)
        real(dp), intent(inout) :: a(:, :)
        real(dp), intent(out) :: tau(:)
        real(dp) :: alpha, xn2, xn, beta, w
        integer :: m, n, k, j
        m = size(a, 1)
        n = size(a, 2)
        do k = 1, n
            alpha = a(k, k)
            xn2 = sum(a(k + 1:m, k)**2)
            ! the sum of squares where it neither underflows nor overflows, else norm2's
            ! scaled sum
            if (xn2 >= tiny(1.0_dp)/epsilon(1.0_dp) .and. xn2 < huge(1.0_dp)) then
                xn = sqrt(xn2)
            else
                xn = norm2(a(k + 1:m, k))
            end if
            if (xn == 0.0_dp) then
                tau(k) = 0.0_dp
                cycle
            end if
            beta = -sign(hypot(alpha, xn), alpha)
            tau(k) = (beta - alpha)/beta
            a(k + 1:m, k) = a(k + 1:m, k)*(1.0_dp/(alpha - beta))
            a(k, k) = beta
            do j = k + 1, n
                w = tau(k)*(a(k, j) + dot_product(a(k + 1:m, k), a(k + 1:m, j)))
                a(k, j) = a(k, j) - w
                a(k + 1:m, j) = a(k + 1:m, j) - w*a(k + 1:m, k)
            end do
        end do
    end subroutine householder

    !> b := Q^T b with Q the product of householder's reflectors in a, tau.
    pure subroutine apply_qt(a, tau, b)
        real(dp), intent(in) :: a(:, :), tau(:)
        real(dp), intent(inout) :: b(:)
        real(dp) :: w
        integer :: m, k
        m = size(a, 1)
        do k = 1, size(a, 2)
            if (tau(k) == 0.0_dp) cycle
            w = tau(k)*(b(k) + dot_product(a(k + 1:m, k), b(k + 1:m)))
            b(k) = b(k) - w
            b(k + 1:m) = b(k + 1:m) - w*a(k + 1:m, k)
        end do
    end subroutine apply_qt

    !> d := R^-1 d, R the upper triangle of a (n x n of it; its diagonal without zeros).
    pure subroutine back_substitute(a, d)
        real(dp), intent(in) :: a(:, :)
        real(dp), intent(inout) :: d(:)
        integer :: n, k
        n = size(d)
        do k = n, 1, -1
            d(k) = (d(k) - dot_product(a(k, k + 1:n), d(k + 1:n)))/a(k, k)
        end do
    end subroutine back_substitute

    !> What the Gauss-Newton step of the Jacobian jac could still lower S = ||r||^2 by, over
    !! S / (m - n) (at least one degree of freedom): the square of that step in standard
    !! errors, the gradient test's measure (see the module header); 0 at S = 0, huge when
    !! the step cannot be had (jac rank deficient: no verdict then).
    function gauss_newton_gain(r, jac) result(gain)
        real(dp), intent(in) :: r(:)            !! residuals (m)
        real(dp), intent(in) :: jac(:, :)       !! their Jacobian (m, n)
        real(dp) :: gain
        real(dp) :: dgn(size(jac, 2)), red
        call linearise(r, jac, dgn, red, gain)
    end function gauss_newton_gain

    !> Huber's weights' roots from residuals without weights: sqrt(min(1, c s / |r_i|)),
    !! s = 1.4826 median |r_i| (ok .false., hw unchanged, when s is 0).
    subroutine huber_roots(r, c, hw, ok)
        real(dp), intent(in) :: r(:), c
        real(dp), intent(inout) :: hw(:)
        logical, intent(out) :: ok
        real(dp) :: s
        integer :: i
        s = 1.4826_dp*median(abs(r))
        ok = s > 0.0_dp
        if (.not. ok) return
        do i = 1, size(r)
            hw(i) = sqrt(min(1.0_dp, c*s/max(abs(r(i)), tiny(1.0_dp))))
        end do
    end subroutine huber_roots

    !> The median of x (a sorted copy: heapsort).
    pure function median(x) result(md)
        real(dp), intent(in) :: x(:)
        real(dp) :: md
        real(dp) :: s(size(x)), t
        integer :: n, i, k
        n = size(x)
        md = 0.0_dp
        if (n == 0) return
        s = x
        do i = n/2, 1, -1
            call sift(s, i, n)
        end do
        do k = n, 2, -1
            t = s(1)
            s(1) = s(k)
            s(k) = t
            call sift(s, 1, k - 1)
        end do
        if (mod(n, 2) == 1) then
            md = s((n + 1)/2)
        else
            md = 0.5_dp*(s(n/2) + s(n/2 + 1))
        end if
    end function median

    !> Heapsort's sift-down of s(i0) within s(1:last).
    pure subroutine sift(s, i0, last)
        real(dp), intent(inout) :: s(:)
        integer, intent(in) :: i0, last
        integer :: root, child
        real(dp) :: tt
        root = i0
        do
            child = 2*root
            if (child > last) exit
            if (child < last) then
                if (s(child + 1) > s(child)) child = child + 1
            end if
            if (.not. (s(child) > s(root))) exit
            tt = s(root)
            s(root) = s(child)
            s(child) = tt
            root = child
        end do
    end subroutine sift

    !> C = scale (J^T J)^-1 from the singular values of J with its columns scaled to unit
    !! norm.  ERR_NUMERIC when J is rank deficient, naming what the data cannot determine:
    !! a parameter they do not depend on, or (condition number beyond 1e10) the parameters
    !! that the smallest singular value's direction mixes.
    subroutine lsq_covariance(jac, scale, cov, stat, names)
        real(dp), intent(in) :: jac(:, :)       !! (m, n)
        real(dp), intent(in) :: scale           !! e.g. 1, or s^2 = chi^2/dof
        real(dp), allocatable, intent(out) :: cov(:, :)
        type(status_t), intent(out) :: stat
        character(len=*), intent(in), optional :: names(:)  !! the parameters' names
        real(dp) :: cn(size(jac, 2)), js(size(jac, 1), size(jac, 2)), sv(size(jac, 2))
        real(dp) :: vt(size(jac, 2), size(jac, 2))
        integer :: n, i, j
        n = size(jac, 2)
        allocate (cov(n, n))
        cov = 0.0_dp
        do j = 1, n
            cn(j) = norm2(jac(:, j))
            if (.not. (cn(j) > 0.0_dp)) then
                call set_error(stat, ERR_NUMERIC, 'the data do not depend on '// &
                    param_name(names, j))
                return
            end if
            js(:, j) = jac(:, j)/cn(j)
        end do
        call la_svd(js, sv, vt, stat)
        if (stat%code /= 0) return
        if (sv(n) < sv(1)/COND_MAX) then
            call set_error(stat, ERR_NUMERIC, 'the data do not tell '// &
                pair_text(vt(n, :), names)//' apart (condition number '//sci(sv(1)/sv(n), 1)// &
                ')')
            return
        end if
        do j = 1, n
            do i = 1, n
                cov(i, j) = scale*sum(vt(:, i)*vt(:, j)/sv**2)/(cn(i)*cn(j))
            end do
        end do
    end subroutine lsq_covariance

    !> The condition number of J with its columns scaled to unit norm (huge with a zero
    !! column; 1 for one column).
    function condition(jac) result(c)
        real(dp), intent(in) :: jac(:, :)
        real(dp) :: c
        real(dp) :: js(size(jac, 1), size(jac, 2)), sv(size(jac, 2)), vt(size(jac, 2), size(jac, 2))
        real(dp) :: cn
        type(status_t) :: st
        integer :: j
        c = 1.0_dp
        if (size(jac, 2) < 2) return
        c = huge(1.0_dp)
        do j = 1, size(jac, 2)
            cn = norm2(jac(:, j))
            if (.not. (cn > 0.0_dp)) return
            js(:, j) = jac(:, j)/cn
        end do
        call la_svd(js, sv, vt, st)
        if (st%code /= 0) return
        if (sv(size(sv)) > 0.0_dp) c = sv(1)/sv(size(sv))
    end function condition

    !> What a rank-deficient J cannot determine, in words: 'the data do not depend on X' or
    !! 'the data do not tell X and Y apart'.
    function inseparable(jac, names) result(s)
        real(dp), intent(in) :: jac(:, :)
        character(len=*), intent(in), optional :: names(:)
        character(len=:), allocatable :: s
        real(dp), allocatable :: cov(:, :)
        type(status_t) :: st
        s = 'the data do not determine every estimated parameter'
        if (size(jac, 2) < 1) return
        if (.not. all(abs(jac) < huge(1.0_dp))) return
        call lsq_covariance(jac, 1.0_dp, cov, st, names)
        if (st%code /= 0 .and. index(st%msg, 'the data') == 1) s = st%msg
    end function inseparable

    !> The two parameters the direction v mixes most (or the one it is, nearly alone).
    function pair_text(v, names) result(s)
        real(dp), intent(in) :: v(:)
        character(len=*), intent(in), optional :: names(:)
        character(len=:), allocatable :: s
        real(dp) :: a(size(v))
        integer :: i1, i2
        a = abs(v)
        i1 = maxloc(a, 1)
        a(i1) = -1.0_dp
        if (size(v) < 2) then
            s = param_name(names, i1)
            return
        end if
        i2 = maxloc(a, 1)
        s = param_name(names, min(i1, i2))//' and '//param_name(names, max(i1, i2))
    end function pair_text

    !> Parameter j's name ('parameter j' without names).
    function param_name(names, j) result(s)
        character(len=*), intent(in), optional :: names(:)
        integer, intent(in) :: j
        character(len=:), allocatable :: s
        s = 'parameter '//itoa(j)
        if (present(names)) then
            if (size(names) >= j) then
                if (len_trim(names(j)) > 0) s = trim(names(j))
            end if
        end if
    end function param_name

    !> Default: the problem gives no Jacobian with its residuals.
    logical function no_jacobian_given(prob)
        class(lsq_problem_t), intent(in) :: prob
        no_jacobian_given = .false.
        call unused(prob)
    end function no_jacobian_given

    !> Default residual_jacobian: the residuals and forward differences with steps of 1e-7
    !! max(|p_j|, 1) (only called when has_jacobian() is .true.; a problem that says so
    !! overrides it).
    subroutine no_residual_jacobian(prob, p, r, jac, stat)
        class(lsq_problem_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:), jac(:, :)
        type(status_t), intent(out) :: stat
        call prob%residual(p, r, stat)
        if (stat%code /= 0) return
        call lsq_jacobian(prob, p, r, 1.0e-7_dp*max(abs(p), 1.0_dp), jac, stat)
    end subroutine no_residual_jacobian

    !> Default jacobian: forward differences with steps h from (p, r); evaluations: n.
    subroutine difference_jacobian(prob, p, r, h, jac, evaluations, stat)
        class(lsq_problem_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)            !! the point
        real(dp), intent(in) :: r(:)            !! r(p), as the problem gave it
        real(dp), intent(in) :: h(:)            !! difference steps, > 0
        real(dp), intent(out) :: jac(:, :)      !! (m, n)
        integer, intent(out) :: evaluations     !! residual evaluations made
        type(status_t), intent(out) :: stat
        call lsq_jacobian(prob, p, r, h, jac, stat)
        evaluations = size(p)
    end subroutine difference_jacobian

    !> Default note_gain: the problem does not use the gain of its points.
    subroutine ignore_gain(prob, gain)
        class(lsq_problem_t), intent(inout) :: prob
        real(dp), intent(in) :: gain            !! g at the point just evaluated
        call unused(prob)
        call unused(gain)
    end subroutine ignore_gain

    !> The Jacobian dr/dp by differences with steps h: forward from (p, r) (n evaluations),
    !! or central (2n evaluations) when `central` is .true.
    subroutine lsq_jacobian(prob, p, r, h, jac, stat, central)
        class(lsq_problem_t), intent(inout) :: prob !! the residuals
        real(dp), intent(in) :: p(:)            !! the point
        real(dp), intent(in) :: r(:)            !! r(p) (used by forward differences)
        real(dp), intent(in) :: h(:)            !! steps, > 0
        real(dp), intent(out) :: jac(:, :)      !! (m, n)
        type(status_t), intent(out) :: stat     !! an evaluation's failure, named
        logical, intent(in), optional :: central
        real(dp) :: pp(size(p)), rp(size(r)), rm(size(r))
        integer :: j
        logical :: c
        c = .false.
        if (present(central)) c = central
        jac = 0.0_dp
        stat%code = 0
        do j = 1, size(p)
            pp = p
            pp(j) = p(j) + h(j)
            call prob%residual(pp, rp, stat)
            if (stat%code /= 0) exit
            if (c) then
                pp(j) = p(j) - h(j)
                call prob%residual(pp, rm, stat)
                if (stat%code /= 0) exit
                jac(:, j) = (rp - rm)/(2.0_dp*h(j))
            else
                jac(:, j) = (rp - r)/h(j)
            end if
        end do
        if (stat%code /= 0) stat%msg = 'difference step of parameter '//itoa(j)//': '//stat%msg
    end subroutine lsq_jacobian

end module estimator
