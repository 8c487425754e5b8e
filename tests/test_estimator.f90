!> Tests of the estimator (module estimator) on its own, on problems with known answers: a
!! weighted straight line against the closed-form regression (estimate, covariance, chi^2,
!! the Gauss-Newton gain), Rosenbrock's valley and Powell's singular function from their
!! published starts, a Jacobian that cannot separate two parameters (named), Huber's loss
!! on a line with outliers against iteratively reweighted least squares done here, chi^2,
!! p-values and coverage against a known noise level over 200 noise seeds, convergence at
!! roundoff ending in success, the domain and failed evaluations.
module test_estimator
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_NUMERIC
    use testing, only: tester_t
    use random, only: rng_t, rng_stream, rng_normal
    use estimator, only: lsq_problem_t, lsq_options_t, lsq_result_t, estimate, &
        gauss_newton_gain, lsq_covariance, DAMP_HALVING, STEP_LARGEST, &
        LOSS_HUBER, CONV_FLOOR, FAIL_EVALUATION
    use unused_arg, only: unused
    use text, only: itoa
    implicit none
    private

    public :: run_estimator_tests

    !> r_i = (a + b t_i - y_i)/u_i: a straight line, weighted.
    type, extends(lsq_problem_t) :: line_t
        real(dp), allocatable :: t(:), y(:), u(:)
        logical :: exact_j = .false.            !! its own Jacobian (else differences)
    contains
        procedure :: residual => line_residual
        procedure :: nres => line_nres
        procedure :: has_jacobian => line_has_jacobian
        procedure :: residual_jacobian => line_residual_jacobian
    end type line_t

    !> r = (10 (x2 - x1^2), 1 - x1): Rosenbrock's valley as least squares.
    type, extends(lsq_problem_t) :: rosenbrock_t
    contains
        procedure :: residual => rosenbrock_residual
        procedure :: nres => two_residuals
    end type rosenbrock_t

    !> Powell's singular function: r = (x1 + 10 x2, 5^(1/2) (x3 - x4), (x2 - 2 x3)^2,
    !! 10^(1/2) (x1 - x4)^2); minimum 0 at the origin, where J is singular.
    type, extends(lsq_problem_t) :: powell_t
    contains
        procedure :: residual => powell_residual
        procedure :: nres => four_residuals
    end type powell_t

    !> r_i = (A exp(-k t_i) + c - y_i)/sigma, with its own Jacobian.
    type, extends(lsq_problem_t) :: decay_t
        real(dp), allocatable :: t(:), y(:)
        real(dp) :: sigma = 1.0_dp
    contains
        procedure :: residual => decay_residual
        procedure :: nres => decay_nres
        procedure :: has_jacobian => decay_has_jacobian
        procedure :: residual_jacobian => decay_residual_jacobian
    end type decay_t

    !> r_i = a t_i - y_i plus a deterministic noise of 1e-12 that changes with a at every
    !! digit: a fit whose residuals stop falling at their roundoff.
    type, extends(lsq_problem_t) :: noisy_t
        real(dp), allocatable :: t(:), y(:)
    contains
        procedure :: residual => noisy_residual
        procedure :: nres => noisy_nres
    end type noisy_t

    !> r = p^2 - 2.25, which cannot be evaluated beyond p = 2 (a failed evaluation).
    type, extends(lsq_problem_t) :: fragile_t
        integer :: failures = 0
    contains
        procedure :: residual => fragile_residual
        procedure :: nres => one_residual
    end type fragile_t

contains

    !> Suite estimator.
    subroutine run_estimator_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        call unused(exe)
        if (t%want('estimator: a weighted straight line against the closed form')) &
            call test_line(t)
        if (t%want('estimator: Rosenbrock''s valley and Powell''s singular function')) &
            call test_rosenbrock(t)
        if (t%want('estimator: a Jacobian that cannot separate two parameters')) &
            call test_rank(t)
        if (t%want('estimator: Huber''s loss on a line with outliers')) call test_huber(t)
        if (t%want('estimator: chi-square against a known noise level')) call test_chi2(t)
        if (t%want('estimator: the fit checks itself against its stated u')) &
            call test_self_check(t)
        if (t%want('estimator: convergence at roundoff ends in success')) call test_roundoff(t)
        if (t%want('estimator: the domain and failed evaluations')) call test_domain(t)
    end subroutine run_estimator_tests

    ! ------------------------------------------------------------------------------------
    !> A line through 25 points with stated u (1/u^2 from 1 to 4) and its exact Jacobian:
    !! the estimate, (J^T J)^-1,
    !! chi^2 and its p-value, the Birge ratio, against the closed-form weighted regression
    !! (a = (Sxx Sy - Sx Sxy)/D, b = (S Sxy - Sx Sy)/D, var a = Sxx/D, var b = S/D,
    !! cov = -Sx/D, D = S Sxx - Sx^2), from a far start, with either damping; the
    !! Gauss-Newton gain at the start is (S - S_min) (m - 2) / S.
    subroutine test_line(t)
        type(tester_t), intent(inout) :: t
        type(line_t) :: ln
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        type(status_t) :: st
        type(rng_t) :: g
        real(dp) :: w(25), s, sx, sy, sxx, sxy, dd, a, b, smin, r0(25), j0(25, 2), gj(2)
        integer :: i, k
        character(len=10) :: how(2) = ['Marquardt ', 'halving   ']
        g = rng_stream(7, 1)
        allocate (ln%t(25), ln%y(25), ln%u(25))
        ln%exact_j = .true.
        do i = 1, 25
            ln%t(i) = 0.4_dp*i - 3.0_dp
            ln%u(i) = 0.5_dp + 0.5_dp*mod(i, 3)/2.0_dp
            ln%y(i) = 1.5_dp - 0.75_dp*ln%t(i) + ln%u(i)*rng_normal(g)
        end do
        w = 1.0_dp/ln%u**2
        s = sum(w)
        sx = sum(w*ln%t)
        sy = sum(w*ln%y)
        sxx = sum(w*ln%t**2)
        sxy = sum(w*ln%t*ln%y)
        dd = s*sxx - sx**2
        a = (sxx*sy - sx*sxy)/dd
        b = (s*sxy - sx*sy)/dd
        smin = sum(w*(a + b*ln%t - ln%y)**2)
        do k = 1, 2
            opts = lsq_options_t()
            opts%gtol = 1.0e-20_dp
            opts%covariance = .true.
            opts%names = [character(len=16) :: 'a', 'b']
            if (k == 2) then
                opts%damping = DAMP_HALVING
                opts%max_jacobians = 20
            end if
            call estimate(ln, [-5.0_dp, 10.0_dp], opts, res, st)
            call t%check('line ('//trim(how(k))//'): converges', st%code == 0 .and. &
                         res%converged)
            call t%check_close('line ('//trim(how(k))//'): a', res%p(1), a, rtol=1.0e-10_dp)
            call t%check_close('line ('//trim(how(k))//'): b', res%p(2), b, rtol=1.0e-10_dp)
            call t%check_close('line ('//trim(how(k))//'): chi^2 the weighted sum of squares', &
                               res%cost, smin, rtol=1.0e-10_dp)
            call t%check('line ('//trim(how(k))//'): dof = m - n', res%dof == 23)
            call t%check_close('line ('//trim(how(k))//'): Birge ratio', res%birge, &
                               sqrt(smin/23.0_dp), rtol=1.0e-10_dp)
            call t%check('line ('//trim(how(k))//'): p-value in (0, 1)', &
                         res%p_value > 0.0_dp .and. res%p_value < 1.0_dp)
            if (.not. allocated(res%cov)) then
                call t%check('line ('//trim(how(k))//'): the covariance', .false.)
                cycle
            end if
            call t%check_close('line ('//trim(how(k))//'): var a = Sxx/D', res%cov(1, 1), &
                               sxx/dd, rtol=1.0e-10_dp)
            call t%check_close('line ('//trim(how(k))//'): var b = S/D', res%cov(2, 2), &
                               s/dd, rtol=1.0e-10_dp)
            call t%check_close('line ('//trim(how(k))//'): cov ab = -Sx/D', res%cov(1, 2), &
                               -sx/dd, rtol=1.0e-10_dp)
            call t%check_close('line ('//trim(how(k))//'): scaled by chi^2/dof', &
                               res%cov_scaled(2, 2), s/dd*smin/23.0_dp, rtol=1.0e-10_dp)
        end do
        ! the gain at the start: what the Gauss-Newton step could still lower S by, in s^2
        do i = 1, 25
            r0(i) = (-5.0_dp + 10.0_dp*ln%t(i) - ln%y(i))/ln%u(i)
            j0(i, :) = [1.0_dp, ln%t(i)]/ln%u(i)
        end do
        call t%check_close('line: the Gauss-Newton gain at the start', &
                           gauss_newton_gain(r0, j0), (sum(r0**2) - smin)*23.0_dp/sum(r0**2), &
                           rtol=1.0e-10_dp)
        ! one damped step (Marquardt, lambda 1, D_j the column norms of J) against
        ! d = -(J^T J + lambda D^2)^-1 J^T r written out for the line's 2 x 2 normal matrix
        opts = lsq_options_t()
        opts%lambda0 = 1.0_dp
        opts%max_jacobians = 1
        call estimate(ln, [-5.0_dp, 10.0_dp], opts, res, st)
        gj = matmul(r0, j0)
        dd = (2.0_dp*s)*(2.0_dp*sxx) - sx**2
        call t%check('line: one damped step taken, then the Jacobians'' limit', &
                     st%code == ERR_NUMERIC .and. res%iterations == 1)
        call t%check_close('line: the damped step in a', res%p(1) + 5.0_dp, &
                           -((2.0_dp*sxx)*gj(1) - sx*gj(2))/dd, rtol=1.0e-12_dp)
        call t%check_close('line: the damped step in b', res%p(2) - 10.0_dp, &
                           -((2.0_dp*s)*gj(2) - sx*gj(1))/dd, rtol=1.0e-12_dp)
    end subroutine test_line

    !> Rosenbrock's valley from (-1.2, 1) to (1, 1) with either damping, and Powell's
    !! singular function from (3, -1, 0, 1) to its minimum 0 at the origin (J singular
    !! there: an exact fit, found to roundoff of its start).
    subroutine test_rosenbrock(t)
        type(tester_t), intent(inout) :: t
        type(rosenbrock_t) :: rb
        type(powell_t) :: pw
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        type(status_t) :: st
        opts%h = [1.0e-8_dp, 1.0e-8_dp]
        call estimate(rb, [-1.2_dp, 1.0_dp], opts, res, st)
        call t%check('Rosenbrock (Marquardt): converges', st%code == 0 .and. res%converged)
        call t%check('Rosenbrock (Marquardt): (1, 1) to 1e-6', all(abs(res%p - 1.0_dp) < 1.0e-6_dp))
        call t%check('Rosenbrock (Marquardt): in few steps', res%iterations < 40)
        opts%damping = DAMP_HALVING
        opts%max_jacobians = 40
        call estimate(rb, [-1.2_dp, 1.0_dp], opts, res, st)
        call t%check('Rosenbrock (halving): converges', st%code == 0 .and. res%converged)
        call t%check('Rosenbrock (halving): (1, 1) to 1e-6', all(abs(res%p - 1.0_dp) < 1.0e-6_dp))
        opts = lsq_options_t()
        opts%max_iter = 200
        call estimate(pw, [3.0_dp, -1.0_dp, 0.0_dp, 1.0_dp], opts, res, st)
        call t%check('Powell singular: converges', st%code == 0 .and. res%converged)
        call t%check('Powell singular: chi^2 below 1e-20 of its start (215)', &
                     res%cost <= 215.0_dp*1.0e-20_dp)
        call t%check('Powell singular: near the origin (1e-4)', all(abs(res%p) < 1.0e-4_dp))
    end subroutine test_rosenbrock

    !> Residuals a + b - y_i: J's two columns are equal.  The covariance says which
    !! parameters the data do not tell apart, by name, and so does the fit with either
    !! damping (Levenberg-Marquardt after finding the sum); a residual that does not depend
    !! on a parameter names it.
    subroutine test_rank(t)
        type(tester_t), intent(inout) :: t
        type(line_t) :: ln
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        type(status_t) :: st
        real(dp) :: jac(10, 3)
        real(dp), allocatable :: cov(:, :)
        integer :: i, k
        character(len=16) :: names(3) = [character(len=16) :: 'offset', 'slope', 'phase']
        character(len=10) :: how(2) = ['Marquardt ', 'halving   ']
        do i = 1, 10
            jac(i, :) = [1.0_dp, 1.0_dp, 0.1_dp*i]
        end do
        call lsq_covariance(jac, 1.0_dp, cov, st, names)
        call t%check('rank: equal columns are ERR_NUMERIC', st%code == ERR_NUMERIC)
        call t%check('rank: ... naming the two parameters ('//trim(st%msg)//')', &
                     index(st%msg, 'offset and slope') > 0)
        jac(:, 2) = 0.0_dp
        call lsq_covariance(jac, 1.0_dp, cov, st, names)
        call t%check('rank: a parameter the data do not depend on, named ('//trim(st%msg)// &
                     ')', st%code == ERR_NUMERIC .and. index(st%msg, 'depend on slope') > 0)
        ! a line whose abscissae are all 1: y = a + b
        allocate (ln%t(10), ln%y(10), ln%u(10))
        ln%t = 1.0_dp
        ln%u = 1.0_dp
        do i = 1, 10
            ln%y(i) = 3.0_dp + 0.01_dp*(-1)**i
        end do
        ! Levenberg-Marquardt finds the sum, then cannot tell whether it has converged (the
        ! Gauss-Newton step does not exist) and says why; Gauss-Newton cannot step at all
        do k = 1, 2
            opts = lsq_options_t()
            if (k == 2) opts%damping = DAMP_HALVING
            opts%names = names(1:2)
            call estimate(ln, [0.0_dp, 0.0_dp], opts, res, st)
            call t%check('rank ('//trim(how(k))//'): ERR_NUMERIC', st%code == ERR_NUMERIC)
            call t%check('rank ('//trim(how(k))//'): the two parameters named ('// &
                         trim(st%msg)//')', index(st%msg, 'offset and slope apart') > 0)
            if (k == 1) call t%check('rank ('//trim(how(k))//'): the sum a + b found', &
                                     abs(sum(res%p) - 3.0_dp) < 1.0e-9_dp)
        end do
    end subroutine test_rank

    !> A line through 40 points with noise 0.01 and 4 of them 1 off: least squares is pulled
    !! away, Huber's loss (3 reweightings) is not, it gives the estimate of iteratively
    !! reweighted least squares done here with the closed-form weighted line, and the
    !! outliers' weights are small.
    subroutine test_huber(t)
        type(tester_t), intent(inout) :: t
        type(line_t) :: ln
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: ls, hub
        type(status_t) :: st
        type(rng_t) :: g
        real(dp) :: w(40), a, b, r(40), sc
        integer :: i, k
        g = rng_stream(11, 2)
        allocate (ln%t(40), ln%y(40), ln%u(40))
        ln%u = 1.0_dp
        do i = 1, 40
            ln%t(i) = 0.1_dp*i
            ln%y(i) = 2.0_dp + 0.5_dp*ln%t(i) + 0.01_dp*rng_normal(g)
        end do
        ln%y([5, 17, 26, 33]) = ln%y([5, 17, 26, 33]) + 1.0_dp
        call estimate(ln, [0.0_dp, 0.0_dp], lsq_options_t(), ls, st)
        call t%check('huber: least squares converges', st%code == 0)
        opts%loss = LOSS_HUBER
        opts%gtol = 1.0e-20_dp
        call estimate(ln, [0.0_dp, 0.0_dp], opts, hub, st)
        call t%check('huber: converges', st%code == 0 .and. hub%converged)
        call t%check('huber: within 0.01 of the line (least squares is not)', &
                     abs(hub%p(1) - 2.0_dp) < 0.01_dp .and. abs(hub%p(2) - 0.5_dp) < 0.01_dp &
                     .and. abs(ls%p(1) - 2.0_dp) > 0.05_dp)
        call t%check('huber: the outliers weigh little, the others fully', &
                     all(hub%robust([5, 17, 26, 33]) < 0.2_dp) .and. &
                     count(hub%robust > 0.999_dp) >= 30)
        ! IRLS here: start from least squares, three times: weights from the residuals
        ! (c = 1.345, s = 1.4826 median |r|), the weighted line in closed form
        w = 1.0_dp
        call weighted_line(ln%t, ln%y, w, a, b)
        do k = 1, 3
            r = a + b*ln%t - ln%y
            sc = 1.4826_dp*median_here(abs(r))
            w = min(1.0_dp, 1.345_dp*sc/max(abs(r), tiny(1.0_dp)))
            call weighted_line(ln%t, ln%y, w, a, b)
        end do
        call t%check_close('huber: a as reweighted least squares', hub%p(1), a, rtol=1.0e-8_dp)
        call t%check_close('huber: b as reweighted least squares', hub%p(2), b, rtol=1.0e-8_dp)
        call t%check_close('huber: the weights'' roots', hub%robust(5), sqrt(w(5)), &
                           rtol=1.0e-6_dp)
    end subroutine test_huber

    !> 200 fits of an exponential decay (A = 2, k = 0.7, c = 0.3) to 40 points with normal
    !! noise of the stated sigma = 0.05: chi^2 averages its dof (37), the p-values average
    !! 1/2, the Birge ratio 1, and sqrt(C_jj) covers each parameter's truth 68 % of the time.
    subroutine test_chi2(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: NS = 200
        type(decay_t) :: dc
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        type(status_t) :: st
        type(rng_t) :: g
        real(dp), parameter :: TRUTH(3) = [2.0_dp, 0.7_dp, 0.3_dp]
        real(dp) :: c2, pv, br, cover
        integer :: i, k, nok
        allocate (dc%t(40), dc%y(40))
        dc%sigma = 0.05_dp
        do i = 1, 40
            dc%t(i) = 0.1_dp*i
        end do
        opts%covariance = .true.
        c2 = 0.0_dp
        pv = 0.0_dp
        br = 0.0_dp
        cover = 0.0_dp
        nok = 0
        do k = 1, NS
            g = rng_stream(2026, k)
            do i = 1, 40
                dc%y(i) = TRUTH(1)*exp(-TRUTH(2)*dc%t(i)) + TRUTH(3) + dc%sigma*rng_normal(g)
            end do
            call estimate(dc, [1.0_dp, 1.0_dp, 0.0_dp], opts, res, st)
            if (st%code /= 0 .or. .not. allocated(res%cov)) cycle
            nok = nok + 1
            c2 = c2 + res%cost
            pv = pv + res%p_value
            br = br + res%birge
            do i = 1, 3
                if (abs(res%p(i) - TRUTH(i)) <= sqrt(res%cov(i, i))) cover = cover + 1.0_dp
            end do
        end do
        call t%check('chi2: every fit converges with its covariance', nok == NS)
        if (nok == 0) return
        call t%check_close('chi2: mean chi^2 = dof (37)', c2/nok, 37.0_dp, &
                           atol=3.0_dp*sqrt(2.0_dp*37.0_dp/nok))
        call t%check_close('chi2: mean p-value 1/2', pv/nok, 0.5_dp, &
                           atol=3.0_dp*sqrt(1.0_dp/12.0_dp/nok))
        call t%check_close('chi2: mean Birge ratio 1', br/nok, 1.0_dp, atol=0.05_dp)
        call t%check_close('chi2: sqrt(C_jj) covers 68 %', cover/(3*nok), 0.6827_dp, &
                           atol=3.0_dp*sqrt(0.6827_dp*0.3173_dp/(3*nok)))
    end subroutine test_chi2

    ! ------------------------------------------------------------------------------------
    !> The self-check.  200 decays with noise of the stated sigma: about 5 % are marked
    !! inconsistent (binomial bounds), and those that are not keep cov.  200 decays whose
    !! noise is 3 times the stated sigma: nearly all are marked, sqrt(cov) covers far below
    !! 68 % and sqrt(cov_fit) (cov times the Birge ratio squared) covers 68 %.  One residual
    !! of 20 sigma: marked, worst names it.  u not stated: cov_fit is cov_scaled.
    subroutine test_self_check(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: NS = 200
        type(decay_t) :: dc
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        type(status_t) :: st
        type(rng_t) :: g
        real(dp), parameter :: TRUTH(3) = [2.0_dp, 0.7_dp, 0.3_dp]
        real(dp) :: cover_cov, cover_fit, noise
        integer :: i, k, ns_ok, marked, marked3, kept_cov
        allocate (dc%t(40), dc%y(40))
        dc%sigma = 0.05_dp
        do i = 1, 40
            dc%t(i) = 0.1_dp*i
        end do
        opts%covariance = .true.
        marked = 0
        marked3 = 0
        kept_cov = 0
        ns_ok = 0
        cover_cov = 0.0_dp
        cover_fit = 0.0_dp
        do k = 1, 2*NS
            noise = merge(1.0_dp, 3.0_dp, k <= NS)*dc%sigma
            g = rng_stream(77, k)
            do i = 1, 40
                dc%y(i) = TRUTH(1)*exp(-TRUTH(2)*dc%t(i)) + TRUTH(3) + noise*rng_normal(g)
            end do
            call estimate(dc, [1.0_dp, 1.0_dp, 0.0_dp], opts, res, st)
            if (st%code /= 0 .or. .not. allocated(res%cov_fit)) cycle
            ns_ok = ns_ok + 1
            if (k <= NS) then
                if (.not. res%consistent) marked = marked + 1
                if (res%consistent .and. maxval(abs(res%cov_fit - res%cov)) == 0.0_dp) &
                    kept_cov = kept_cov + 1
            else
                if (.not. res%consistent) marked3 = marked3 + 1
                do i = 1, 3
                    if (abs(res%p(i) - TRUTH(i)) <= sqrt(res%cov(i, i))) &
                        cover_cov = cover_cov + 1.0_dp
                    if (abs(res%p(i) - TRUTH(i)) <= sqrt(res%cov_fit(i, i))) &
                        cover_fit = cover_fit + 1.0_dp
                end do
            end if
        end do
        call t%check('self-check: every fit has its covariance', ns_ok == 2*NS)
        ! 5 % of 200: 10, sd 3.1
        call t%check('self-check: about 5 % of fits at the stated noise are marked ('// &
                     itoa(marked)//')', marked >= 1 .and. marked <= 20)
        call t%check('self-check: a consistent fit keeps cov', kept_cov == NS - marked)
        call t%check('self-check: noise 3 times its u: nearly all marked ('// &
                     itoa(marked3)//')', marked3 >= NS - 2)
        call t%check('self-check: noise 3 times its u: sqrt(cov) covers far below 68 %', &
                     cover_cov/(3*NS) < 0.4_dp)
        call t%check_close('self-check: noise 3 times its u: sqrt(cov_fit) covers 68 %', &
                           cover_fit/(3*NS), 0.6827_dp, &
                           atol=4.0_dp*sqrt(0.6827_dp*0.3173_dp/(3*NS)))
        ! one outlier of 20 sigma at point 17
        g = rng_stream(78, 1)
        do i = 1, 40
            dc%y(i) = TRUTH(1)*exp(-TRUTH(2)*dc%t(i)) + TRUTH(3) + dc%sigma*rng_normal(g)
        end do
        dc%y(17) = dc%y(17) + 20.0_dp*dc%sigma
        call estimate(dc, [1.0_dp, 1.0_dp, 0.0_dp], opts, res, st)
        call t%check('self-check: an outlier of 20 sigma is marked and named', &
                     st%code == 0 .and. .not. res%consistent .and. res%worst == 17)
        if (st%code == 0 .and. allocated(res%cov_fit)) &
            call t%check_close('self-check: cov_fit = cov times the Birge ratio squared', &
                               res%cov_fit(2, 2), res%cov(2, 2)*res%birge**2, rtol=1.0e-12_dp)
        opts%u_stated = .false.
        call estimate(dc, [1.0_dp, 1.0_dp, 0.0_dp], opts, res, st)
        if (st%code == 0 .and. allocated(res%cov_fit)) then
            call t%check('self-check: u from the scatter: cov_fit is cov_scaled', &
                         maxval(abs(res%cov_fit - res%cov_scaled)) == 0.0_dp .and. &
                         res%consistent)
        else
            call t%check('self-check: u from the scatter: the fit converges', .false.)
        end if
    end subroutine test_self_check

    !> A line whose residuals carry a noise of 1e-12 that changes with the parameter at
    !! every digit: with the gradient, step, reduction and exact-fit tests off, no step lowers
    !! the sum any more near the answer, and that floor is a success (the undamped step below
    !! 1e-9 of the parameter), with either damping; the answer to 1e-10.
    subroutine test_roundoff(t)
        type(tester_t), intent(inout) :: t
        type(noisy_t) :: nz
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        type(status_t) :: st
        integer :: i, k
        character(len=10) :: how(2) = ['Marquardt ', 'halving   ']
        allocate (nz%t(30), nz%y(30))
        do i = 1, 30
            nz%t(i) = 0.1_dp*i
            nz%y(i) = 2.0_dp*nz%t(i)
        end do
        do k = 1, 2
            opts = lsq_options_t()
            opts%gtol = 0.0_dp
            opts%xtol = 0.0_dp
            if (k == 2) then
                ! Gauss-Newton accepts any step that does not raise the sum: its steps at
                ! the noise end by the step test (below 1e-15 of the parameter) or the floor
                opts%damping = DAMP_HALVING
                opts%xtol = 1.0e-15_dp
            end if
            opts%ftol = 0.0_dp
            opts%exact = 0.0_dp
            opts%floor_gain = 0.0_dp
            opts%floor_xtol = 1.0e-9_dp
            opts%step_norm = STEP_LARGEST
            opts%max_iter = 1000
            opts%max_jacobians = 1000
            call estimate(nz, [0.5_dp], opts, res, st)
            call t%check('roundoff ('//trim(how(k))//'): a success', st%code == 0 .and. &
                         res%converged)
            if (k == 1) call t%check('roundoff ('//trim(how(k))//'): ended at the floor', &
                                     res%ended == CONV_FLOOR)
            call t%check_close('roundoff ('//trim(how(k))//'): the answer', res%p(1), 2.0_dp, &
                               rtol=1.0e-10_dp)
        end do
    end subroutine test_roundoff

    !> A bound keeps every point tried inside the domain (the answer outside: no
    !! convergence, the parameter still above the bound); a failed evaluation is a rejected
    !! step (the answer found beyond it), or ends the fit when the options say so.
    subroutine test_domain(t)
        type(tester_t), intent(inout) :: t
        type(line_t) :: ln
        type(fragile_t) :: fr
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        type(status_t) :: st
        ! y = -1 + 0 t: the answer a = -1, the domain a > 0
        allocate (ln%t(3), ln%y(3), ln%u(3))
        ln%t = [1.0_dp, 2.0_dp, 3.0_dp]
        ln%y = -1.0_dp
        ln%u = 1.0_dp
        opts%damping = DAMP_HALVING
        opts%max_jacobians = 30
        opts%lower = [0.0_dp, -huge(1.0_dp)]
        call estimate(ln, [1.0_dp, 0.0_dp], opts, res, st)
        call t%check('domain: the answer outside: no convergence', st%code == ERR_NUMERIC &
                     .and. .not. res%converged)
        call t%check('domain: the parameter stays inside', res%p(1) > 0.0_dp)
        opts = lsq_options_t()
        opts%damping = DAMP_HALVING
        call estimate(fr, [0.1_dp], opts, res, st)
        call t%check('failed evaluation: a rejected step, the answer beyond it', &
                     st%code == 0 .and. abs(res%p(1) - 1.5_dp) < 1.0e-9_dp .and. &
                     fr%failures > 0)
        opts%fail_on_error = .true.
        call estimate(fr, [0.1_dp], opts, res, st)
        call t%check('failed evaluation: ends the fit when asked, with its status', &
                     st%code == ERR_NUMERIC .and. res%ended == FAIL_EVALUATION .and. &
                     index(st%msg, 'beyond p = 2') > 0)
    end subroutine test_domain

    ! ------------------------------------------------------------------------------------
    !> The weighted straight line y = a + b t in closed form.
    pure subroutine weighted_line(x, y, w, a, b)
        real(dp), intent(in) :: x(:), y(:), w(:)
        real(dp), intent(out) :: a, b
        real(dp) :: s, sx, sy, sxx, sxy, dd
        s = sum(w)
        sx = sum(w*x)
        sy = sum(w*y)
        sxx = sum(w*x**2)
        sxy = sum(w*x*y)
        dd = s*sxx - sx**2
        a = (sxx*sy - sx*sxy)/dd
        b = (s*sxy - sx*sy)/dd
    end subroutine weighted_line

    !> The median (insertion sort of a copy).
    pure real(dp) function median_here(x) result(m)
        real(dp), intent(in) :: x(:)
        real(dp) :: s(size(x)), v
        integer :: i, j, n
        n = size(x)
        s = x
        do i = 2, n
            v = s(i)
            j = i - 1
            do while (j >= 1)
                if (s(j) <= v) exit
                s(j + 1) = s(j)
                j = j - 1
            end do
            s(j + 1) = v
        end do
        m = s((n + 1)/2)
        if (mod(n, 2) == 0) m = 0.5_dp*(s(n/2) + s(n/2 + 1))
    end function median_here

    subroutine line_residual(prob, p, r, stat)
        class(line_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        stat%code = 0
        r = (p(1) + p(2)*prob%t - prob%y)/prob%u
    end subroutine line_residual

    integer function line_nres(prob) result(n)
        class(line_t), intent(in) :: prob
        n = size(prob%t)
    end function line_nres

    logical function line_has_jacobian(prob)
        class(line_t), intent(in) :: prob
        line_has_jacobian = prob%exact_j
    end function line_has_jacobian

    subroutine line_residual_jacobian(prob, p, r, jac, stat)
        class(line_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:), jac(:, :)
        type(status_t), intent(out) :: stat
        call prob%residual(p, r, stat)
        jac(:, 1) = 1.0_dp/prob%u
        jac(:, 2) = prob%t/prob%u
    end subroutine line_residual_jacobian

    subroutine rosenbrock_residual(prob, p, r, stat)
        class(rosenbrock_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        call unused(prob)
        stat%code = 0
        r = [10.0_dp*(p(2) - p(1)**2), 1.0_dp - p(1)]
    end subroutine rosenbrock_residual

    integer function two_residuals(prob) result(n)
        class(rosenbrock_t), intent(in) :: prob
        call unused(prob)
        n = 2
    end function two_residuals

    subroutine powell_residual(prob, p, r, stat)
        class(powell_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        call unused(prob)
        stat%code = 0
        r = [p(1) + 10.0_dp*p(2), sqrt(5.0_dp)*(p(3) - p(4)), (p(2) - 2.0_dp*p(3))**2, &
             sqrt(10.0_dp)*(p(1) - p(4))**2]
    end subroutine powell_residual

    integer function four_residuals(prob) result(n)
        class(powell_t), intent(in) :: prob
        call unused(prob)
        n = 4
    end function four_residuals

    subroutine decay_residual(prob, p, r, stat)
        class(decay_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        stat%code = 0
        r = (p(1)*exp(-p(2)*prob%t) + p(3) - prob%y)/prob%sigma
    end subroutine decay_residual

    integer function decay_nres(prob) result(n)
        class(decay_t), intent(in) :: prob
        n = size(prob%t)
    end function decay_nres

    logical function decay_has_jacobian(prob)
        class(decay_t), intent(in) :: prob
        call unused(prob)
        decay_has_jacobian = .true.
    end function decay_has_jacobian

    subroutine decay_residual_jacobian(prob, p, r, jac, stat)
        class(decay_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:), jac(:, :)
        type(status_t), intent(out) :: stat
        call prob%residual(p, r, stat)
        jac(:, 1) = exp(-p(2)*prob%t)/prob%sigma
        jac(:, 2) = -p(1)*prob%t*exp(-p(2)*prob%t)/prob%sigma
        jac(:, 3) = 1.0_dp/prob%sigma
    end subroutine decay_residual_jacobian

    subroutine noisy_residual(prob, p, r, stat)
        class(noisy_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        integer :: i
        stat%code = 0
        do i = 1, size(r)
            r(i) = p(1)*prob%t(i) - prob%y(i) + 1.0e-12_dp*sin(1.0e15_dp*p(1) + 1.7_dp*i)
        end do
    end subroutine noisy_residual

    integer function noisy_nres(prob) result(n)
        class(noisy_t), intent(in) :: prob
        n = size(prob%t)
    end function noisy_nres

    subroutine fragile_residual(prob, p, r, stat)
        class(fragile_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        stat%code = 0
        r = p(1)**2 - 2.25_dp
        if (p(1) > 2.0_dp) then
            prob%failures = prob%failures + 1
            call set_error(stat, ERR_NUMERIC, 'the model cannot be evaluated beyond p = 2')
        end if
    end subroutine fragile_residual

    integer function one_residual(prob) result(n)
        class(fragile_t), intent(in) :: prob
        call unused(prob)
        n = 1
    end function one_residual

end module test_estimator
