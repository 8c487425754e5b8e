!> Nonlinear least squares by Levenberg-Marquardt, on LAPACK.
!!
!! Minimise S(p) = ||r(p)||^2 over n parameters p for m >= n residuals r (a problem extends
!! lsq_problem_t and gives r(p); a failed evaluation, e.g. a model that leaves its range,
!! returns a status and is treated as a rejected step).  Written here from the published
!! descriptions:
!!
!! * K. Levenberg, "A method for the solution of certain non-linear problems in least
!!   squares", Q. Appl. Math. 2 (1944); D. W. Marquardt, "An algorithm for least-squares
!!   estimation of nonlinear parameters", J. SIAM 11 (1963): the step solves
!!   min ||J d + r||^2 + lambda ||D d||^2, i.e. (J^T J + lambda D^2) d = -J^T r; a large
!!   lambda gives a short gradient step, a small one the Gauss-Newton step.
!! * J. J. Moré, "The Levenberg-Marquardt algorithm: implementation and theory", Lecture
!!   Notes in Math. 630 (1978): the scaling D_j = max over the iterations of the column
!!   norms ||J(:,j)|| (the method is then invariant to the parameters' units), the step
!!   computed without forming J^T J (here: LAPACK DGELS on the stacked matrix
!!   [J; sqrt(lambda) D], a QR factorisation), and the gain ratio
!!   rho = (S(p) - S(p + d)) / (S(p) - ||J d + r||^2) of the actual to the predicted
!!   reduction deciding acceptance.
!! * The update of lambda from rho (H. B. Nielsen, "Damping parameter in Marquardt's
!!   method", IMM-REP-1999-05, DTU; K. Madsen, H. B. Nielsen & O. Tingleff, "Methods for
!!   non-linear least squares problems", 2004): on acceptance (rho > 0) lambda is
!!   multiplied by max(1/3, 1 - (2 rho - 1)^3) and nu = 2; on rejection lambda by nu and nu
!!   doubled.
!! * J by forward differences r(p + h_j e_j) - r(p) over h_j (lsq_jacobian: central
!!   differences on request, for the covariance at the solution), or the problem's own J
!!   (has_jacobian, residual_jacobian: e.g. from forward sensitivities), taken with the
!!   residuals at every point tried: an accepted step then costs no further evaluation.
!! * Convergence is judged by the gain the undamped (Gauss-Newton) step of the current
!!   Jacobian could still make, g = (S - min ||J d + r||^2) (m - n) / S: the fall of chi^2
!!   measured in the residuals' own variance s^2 = S / (m - n), i.e. the square of the
!!   remaining step in standard errors.  Converged when g <= chi2_tol (1e-4: a step below
!!   1e-2 standard errors), or after an accepted step with ||D d|| <= xtol (||D p|| + xtol)
!!   or a relative reduction of S below ftol (predicted too) while g <= 1, or when no step
!!   is accepted any more (lambda beyond 1e16: not even the shortest steepest-descent step
!!   lowers S) while g <= 1 or the last accepted step met the step test: a minimum at the
!!   floor set by the noise of the residuals and of the difference Jacobian (here: the
!!   model's integration error, about rtol), where the promised gain is that noise's; or
!!   when S has fallen below 1e-20 of its start (an exact fit, to roundoff, where g
!!   measures roundoff).  A small step with much to gain (g > 1) is no convergence while
!!   steps are still accepted: it is what a fit pressed against parameters the model
!!   cannot take looks like.  Failure (ERR_NUMERIC): max_iter iterations, or lambda beyond
!!   1e16 with g > 1 and no small last step.
!!
!! No routine stops; failures come back in status_t.
module least_squares
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC
    use lapack_wrap, only: la_lstsq
    use text, only: itoa, sci
    use unused_arg, only: unused
    implicit none
    private

    !> A least-squares problem: residuals r(p) (m of them) of n parameters.
    type, abstract, public :: lsq_problem_t
    contains
        procedure(residual_i), deferred :: residual
        procedure :: has_jacobian => no_jacobian_given
        procedure :: residual_jacobian => no_residual_jacobian
    end type lsq_problem_t

    abstract interface
        !> r(p); stat /= 0 when p cannot be evaluated (a step there is rejected).
        subroutine residual_i(prob, p, r, stat)
            import :: lsq_problem_t, dp, status_t
            class(lsq_problem_t), intent(inout) :: prob
            real(dp), intent(in) :: p(:)
            real(dp), intent(out) :: r(:)
            type(status_t), intent(out) :: stat
        end subroutine residual_i
    end interface

    !> Options of lm_fit.
    type, public :: lsq_options_t
        integer :: max_iter = 60                !! most iterations (accepted or rejected steps)
        real(dp) :: xtol = 1.0e-9_dp            !! relative size of the last step
        real(dp) :: ftol = 1.0e-13_dp           !! relative reduction of S
        real(dp) :: lambda0 = 1.0e-3_dp         !! first lambda (with D the column norms)
        real(dp) :: chi2_tol = 1.0e-4_dp        !! gain in chi^2 left (see the header)
    end type lsq_options_t

    !> What lm_fit found.
    type, public :: lsq_result_t
        real(dp), allocatable :: p(:)           !! parameters (the last accepted)
        real(dp), allocatable :: r(:)           !! residuals there
        real(dp), allocatable :: jac(:, :)      !! the last forward-difference Jacobian
        real(dp) :: cost = 0.0_dp               !! S = ||r||^2
        real(dp) :: lambda = 0.0_dp             !! the damping at the end (a next fit from
                                                !! here may start with it)
        integer :: iterations = 0               !! steps tried
        integer :: evaluations = 0              !! residual evaluations (Jacobians included)
        logical :: converged = .false.
    end type lsq_result_t

    public :: lm_fit, lsq_jacobian, problem_jacobian, gauss_newton_gain

    !> Fall of S (from its start) that makes an exact fit, to roundoff.
    real(dp), parameter :: EXACT_FIT = 1.0e-20_dp

contains

    !> Levenberg-Marquardt from p0 (see the module header).  h(j) > 0 is the difference
    !! step of parameter j.  On failure res holds the last accepted point and stat says
    !! why (ERR_NUMERIC), or carries the failure of the first evaluation.
    subroutine lm_fit(prob, p0, h, m, opts, res, stat)
        class(lsq_problem_t), intent(inout) :: prob !! the residuals
        real(dp), intent(in) :: p0(:)           !! start
        real(dp), intent(in) :: h(:)            !! difference steps, > 0
        integer, intent(in) :: m                !! number of residuals, >= size(p0)
        type(lsq_options_t), intent(in) :: opts
        type(lsq_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: a(:, :), b(:), rt(:), jd(:), jt(:, :)
        real(dp) :: dvec(size(p0)), dstep(size(p0)), pt(size(p0)), lambda, nu, st, pred, rho
        real(dp) :: dnorm, pnorm, gain, cost0
        logical :: small_step, last_small, analytic
        type(status_t) :: s2
        integer :: n, j
        n = size(p0)
        allocate (res%p(n), res%r(m), res%jac(m, n), a(m + n, n), b(m + n), rt(m), jd(m))
        res%p = p0
        analytic = prob%has_jacobian()
        if (analytic) then
            allocate (jt(m, n))
            call prob%residual_jacobian(res%p, res%r, res%jac, stat)
            res%evaluations = 1
            if (stat%code /= 0) return
        else
            call prob%residual(res%p, res%r, stat)
            res%evaluations = 1
            if (stat%code /= 0) return
            call lsq_jacobian(prob, res%p, res%r, h, res%jac, stat)
            res%evaluations = res%evaluations + n
            if (stat%code /= 0) return
        end if
        res%cost = sum(res%r**2)
        cost0 = res%cost
        dvec = 0.0_dp
        call scale_columns()
        gain = gauss_newton_gain(res%r, res%jac)
        res%converged = gain <= opts%chi2_tol
        if (res%converged) return
        lambda = opts%lambda0
        res%lambda = lambda
        nu = 2.0_dp
        last_small = .false.
        do while (res%iterations < opts%max_iter)
            res%iterations = res%iterations + 1
            if (res%cost == 0.0_dp) then
                res%converged = .true.
                return
            end if
            ! the step: min ||J d + r||^2 + lambda ||D d||^2 as one least-squares problem
            a(1:m, :) = res%jac
            a(m + 1:, :) = 0.0_dp
            do j = 1, n
                a(m + j, j) = sqrt(lambda)*dvec(j)
            end do
            b(1:m) = -res%r
            b(m + 1:) = 0.0_dp
            call la_lstsq(a, b, dstep, stat)
            if (stat%code /= 0) then
                stat%msg = 'Levenberg-Marquardt step: '//stat%msg
                return
            end if
            jd = matmul(res%jac, dstep)
            pred = res%cost - sum((res%r + jd)**2)
            pt = res%p + dstep
            if (analytic) then
                call prob%residual_jacobian(pt, rt, jt, s2)
            else
                call prob%residual(pt, rt, s2)
            end if
            res%evaluations = res%evaluations + 1
            rho = -1.0_dp
            if (s2%code == 0) then
                st = sum(rt**2)
                if (pred > 0.0_dp) rho = (res%cost - st)/pred
            end if
            if (rho > 0.0_dp) then
                ! accepted
                dnorm = norm2(dvec*dstep)
                pnorm = norm2(dvec*res%p)
                small_step = dnorm <= opts%xtol*(pnorm + opts%xtol) .or. &
                    (res%cost - st <= opts%ftol*res%cost .and. pred <= opts%ftol*res%cost)
                res%p = pt
                res%r = rt
                res%cost = st
                lambda = lambda*max(1.0_dp/3.0_dp, 1.0_dp - (2.0_dp*rho - 1.0_dp)**3)
                res%lambda = lambda
                nu = 2.0_dp
                if (analytic) then
                    res%jac = jt
                else
                    call lsq_jacobian(prob, res%p, res%r, h, res%jac, stat)
                    res%evaluations = res%evaluations + n
                    if (stat%code /= 0) then
                        stat%msg = 'Levenberg-Marquardt Jacobian: '//stat%msg
                        return
                    end if
                end if
                call scale_columns()
                gain = gauss_newton_gain(res%r, res%jac)
                res%converged = gain <= opts%chi2_tol .or. (small_step .and. gain <= 1.0_dp) &
                                .or. res%cost <= EXACT_FIT*cost0
                if (res%converged) return
                last_small = small_step
            else
                lambda = lambda*nu
                nu = 2.0_dp*nu
                if (lambda > 1.0e16_dp) then
                    ! no step along the whole path, down to the steepest descent's, lowers S:
                    ! a minimum to the residuals' roundoff.  Converged when what Gauss-Newton
                    ! still promises is below one unit of chi^2 (the parameters are within a
                    ! fraction of their standard errors), or the last accepted step met the
                    ! step test
                    res%converged = gain <= 1.0_dp .or. last_small .or. &
                                    res%cost <= EXACT_FIT*cost0
                    if (res%converged) return
                    exit
                end if
            end if
        end do
        if (gain < huge(1.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'Levenberg-Marquardt did not converge in '// &
                itoa(res%iterations)//' steps (lambda = '//sci(lambda, 1)//'; the '// &
                'Gauss-Newton step would still lower chi^2 by '//sci(gain, 1)//')')
        else
            call set_error(stat, ERR_NUMERIC, 'Levenberg-Marquardt did not converge in '// &
                itoa(res%iterations)//' steps (lambda = '//sci(lambda, 1)//'; the Jacobian '// &
                'is rank deficient: the data do not determine every estimated parameter)')
        end if
    contains
        !> Moré's scaling: D_j = the largest column norm of J seen so far (never 0).
        subroutine scale_columns()
            integer :: jj
            do jj = 1, n
                dvec(jj) = max(dvec(jj), norm2(res%jac(:, jj)))
                if (.not. (dvec(jj) > 0.0_dp)) dvec(jj) = 1.0_dp
            end do
        end subroutine scale_columns
    end subroutine lm_fit

    !> What the Gauss-Newton step of the Jacobian jac could still lower S = ||r||^2 by, over
    !! S / (m - n) (at least one degree of freedom): the square of that step in standard
    !! errors, lm_fit's measure of convergence (see the module header); 0 at S = 0, huge
    !! when the step cannot be had (jac rank deficient: no verdict then).
    function gauss_newton_gain(r, jac) result(gain)
        real(dp), intent(in) :: r(:)            !! residuals (m)
        real(dp), intent(in) :: jac(:, :)       !! their Jacobian (m, n)
        real(dp) :: gain
        real(dp) :: dgn(size(jac, 2)), cost
        type(status_t) :: st2
        gain = huge(1.0_dp)
        call la_lstsq(jac, -r, dgn, st2)
        if (st2%code /= 0) return
        cost = sum(r**2)
        if (cost > 0.0_dp) then
            gain = (cost - sum((r + matmul(jac, dgn))**2))*max(1, size(r) - size(jac, 2))/cost
        else
            gain = 0.0_dp
        end if
    end function gauss_newton_gain

    !> Default: the problem gives no Jacobian of its own (lm_fit takes differences).
    logical function no_jacobian_given(prob)
        class(lsq_problem_t), intent(in) :: prob
        call unused(prob)
        no_jacobian_given = .false.
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

    !> The Jacobian at p: the problem's own when it has one (residual_jacobian), else
    !! differences with steps h (central when `central`); r gets r(p).  evaluations counts
    !! the residual evaluations.
    subroutine problem_jacobian(prob, p, r, h, jac, evaluations, stat, central)
        class(lsq_problem_t), intent(inout) :: prob !! the residuals
        real(dp), intent(in) :: p(:)            !! the point
        real(dp), intent(inout) :: r(:)         !! r(p) (in: used by forward differences)
        real(dp), intent(in) :: h(:)            !! difference steps, > 0
        real(dp), intent(out) :: jac(:, :)      !! (m, n)
        integer, intent(out) :: evaluations
        type(status_t), intent(out) :: stat
        logical, intent(in), optional :: central
        logical :: c
        c = .false.
        if (present(central)) c = central
        if (prob%has_jacobian()) then
            call prob%residual_jacobian(p, r, jac, stat)
            evaluations = 1
        else
            call lsq_jacobian(prob, p, r, h, jac, stat, central)
            evaluations = size(p)*merge(2, 1, c)
        end if
    end subroutine problem_jacobian

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

end module least_squares
