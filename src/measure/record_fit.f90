!> The fit of the paper's model to a record (the record analysis of identify): the model at
!! the record's sample times (record_model), the least-squares problem of the estimated
!! parameters (record_fit_t: I1 and any of c_v, c_q, the release amplitude, t0), the fit on
!! growing windows (fit_record), its covariance and the inputs' sensitivities (the
!! first-order budget), the Monte Carlo's samples (record_mc_task_t), and records made by
!! the program itself (make_record).  See module identify for the method.
module record_fit
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC
    use text, only: itoa, sci
    use deck, only: deck_t, estimated
    use output_io, only: out_files_t, all_finite
    use geometry, only: pendulum_t
    use bifilar_model, only: NSTATE, motion_t, motion_parts_t, evaluate
    use rig, only: rig_t, start_t, accuracy_t, rig_of, start_of, accuracy_of, make_pendulum, &
        start_state, move_b_prime
    use kane_run, only: kane_run_start, kane_run_t
    use run_loop, only: stepped_model_t, row_sink_t, drive
    use least_squares, only: lsq_problem_t, lsq_options_t, lsq_result_t, lm_fit
    use lapack_wrap, only: la_lstsq, la_svd
    use random, only: rng_t, rng_stream, rng_normal
    use records, only: record_t, mean_period
    use monte_carlo, only: mc_task_t
    implicit none
    private

    !> Parameters a record fit can estimate (deck ESTIMATES_ALLOWED), in this order.
    integer, parameter, public :: P_I1 = 1, P_CV = 2, P_CQ = 3, P_AMP = 4, P_T0 = 5
    character(len=9), parameter, public :: PARAM_NAMES(5) = [character(len=9) :: 'I1', 'c_v', 'c_q', &
        'amplitude', 't0']

    !> The record fit as a least-squares problem: residuals ((model - measured)/u_i) over the
    !! first nuse samples.
    type, extends(lsq_problem_t), public :: record_fit_t
        type(rig_t) :: rg                       !! the rig, every held value (inputs)
        type(start_t) :: st                     !! the start (its amplitude may be fitted)
        type(accuracy_t) :: acc                 !! the model runs' accuracy
        integer :: seed = 1                     !! the Monte Carlo's seed
        type(record_t) :: rec                   !! the record (values perturbed by Monte Carlo)
        integer :: np = 0                       !! parameters estimated
        integer :: which(5) = 0                 !! P_* of each estimated parameter
        real(dp) :: t0 = 0.0_dp                 !! release time (s), when held
        logical :: rate = .false.               !! quantity = 'rate'
        integer :: nuse = 0                     !! samples fitted (the window)
        real(dp), allocatable :: w(:)           !! 1/u_i (1 without column 3)
    contains
        procedure :: residual => record_residual
    end type record_fit_t

    !> The model's value at the record's sample times (a sink of the run loop).
    type, extends(row_sink_t) :: record_sink_t
        logical :: rate = .false.
        type(pendulum_t) :: p                   !! for W = omega . n3
        real(dp), allocatable :: vals(:)        !! theta4 (rad) or W (rad per unit tau)
    contains
        procedure :: take => record_take
    end type record_sink_t

    !> The samples of a record fit's Monte Carlo (record_mc_point) as a sweep: the fit
    !! problem, the estimate the samples start from, its Jacobian and first-order u, s, and
    !! the inputs drawn; built by record_mc_task from the deck, the record and the payload.
    type, extends(mc_task_t), public :: record_mc_task_t
        type(record_fit_t) :: prob              !! the fit (deck, record, weights)
        real(dp), allocatable :: phat(:)        !! the estimate
        real(dp), allocatable :: jac(:, :)      !! the Jacobian there (samples, parameters)
        real(dp), allocatable :: u_p(:)         !! first-order u of each parameter
        real(dp) :: sigma = 0.0_dp              !! s of the covariance
        real(dp), allocatable :: xval(:), ux(:) !! the inputs drawn: values, u
    contains
        procedure :: sample => record_mc_point
    end type record_mc_task_t

    public :: record_model, fit_problem, fit_record, covariance, input_sensitivity
    public :: set_input, budget_inputs, record_mc_task, explain_fit_failure, make_record

    real(dp), parameter, public :: H_REL = 1.0e-5_dp        !! relative difference step of the model
    real(dp), parameter :: DAMP_REF = 1.0e-3_dp     !! scale of c_v, c_q (model's units)
    real(dp), parameter :: COND_MAX = 1.0e10_dp     !! largest condition number of J (scaled)

contains

    !> The model at the record's first n sample times, for the rig rg started by st with
    !! release at t0 (s): theta4 (rad) or W = omega . n3 (rad/s) when rate.  A sample before
    !! t0 sees the start.  The model runs through the run loop (accuracy acc: rtol, atol,
    !! integrator), in memory.
    subroutine record_model(rg, st, acc, t, t0, rate, vals, stat)
        type(rig_t), intent(in) :: rg           !! the rig (I1, damping as fitted)
        type(start_t), intent(in) :: st         !! the start (amplitude as fitted)
        type(accuracy_t), intent(in) :: acc     !! rtol, atol, integrator
        real(dp), intent(in) :: t(:)            !! sample times (s), increasing
        real(dp), intent(in) :: t0              !! release (s)
        logical, intent(in) :: rate             !! W instead of theta4
        real(dp), intent(out) :: vals(:)        !! the model at t(1:size(vals))
        type(status_t), intent(out) :: stat     !! the start's or the run's failure
        type(pendulum_t) :: p
        type(kane_run_t) :: m
        type(record_sink_t) :: sink
        real(dp) :: y0(NSTATE), th0(5), s, v0
        real(dp), allocatable :: taus(:)
        integer :: n, i0, i
        n = size(vals)
        vals = 0.0_dp
        call make_pendulum(rg, p, stat)
        if (stat%code /= 0) return
        call start_state(st, p, y0, th0, stat)
        if (stat%code /= 0) return
        s = sqrt(rg%g/rg%b_prime)               ! tau per second
        sink%rate = rate
        sink%p = p
        call sample_value(sink, y0, th0(3), v0, stat)
        if (stat%code /= 0) return
        i0 = n + 1
        do i = 1, n
            if (t(i) >= t0) then
                i0 = i
                exit
            end if
            vals(i) = v0
        end do
        if (rate) vals(1:i0 - 1) = vals(1:i0 - 1)*s
        if (i0 > n) return
        allocate (taus(0:n - i0), sink%vals(0:n - i0))
        taus = (t(i0:n) - t0)*s
        if (taus(n - i0) <= 0.0_dp) then
            vals(i0:n) = v0*merge(s, 1.0_dp, rate)
            return
        end if
        call kane_run_start(m, p, y0, th0(3), acc%rtol, acc%atol, acc%method, &
                            taus(n - i0), 'raise &integration rtol/atol', stat)
        if (stat%code /= 0) return
        call drive(m, taus, sink, stat)
        if (stat%code /= 0) return
        vals(i0:n) = sink%vals
        if (rate) vals(i0:n) = vals(i0:n)*s
    end subroutine record_model

    !> theta4 (rad) or W = omega . n3 (rad per unit tau) of a chart state.
    subroutine sample_value(sink, y, th3, v, stat)
        type(record_sink_t), intent(in) :: sink
        real(dp), intent(in) :: y(NSTATE)
        real(dp), intent(in) :: th3
        real(dp), intent(out) :: v
        type(status_t), intent(out) :: stat
        type(motion_t) :: mo
        stat%code = 0
        if (.not. sink%rate) then
            v = y(4)
            return
        end if
        call evaluate(sink%p, y, th3, mo, stat, motion_parts_t(.false., .false., .false., .false.))
        v = mo%omega(3)
    end subroutine sample_value

    !> One sample of the model (record_sink_t).
    subroutine record_take(sink, m, k, t, y, stat)
        class(record_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k                !! sample (from 0)
        real(dp), intent(in) :: t               !! its tau
        real(dp), intent(in) :: y(:)            !! chart state there
        type(status_t), intent(out) :: stat
        real(dp) :: th3
        th3 = 0.0_dp
        select type (m)
        type is (kane_run_t)
            th3 = m%th3
        end select
        call sample_value(sink, y, th3, sink%vals(k), stat)
        if (stat%code /= 0) stat%msg = stat%msg//' at tau = '//sci(t)
    end subroutine record_take

    !> The rig and start with the parameters p of the fit set (I1, c_v, c_q, amplitude), and
    !! t0.
    subroutine apply_parameters(prob, p, rg, st, t0)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: p(:)
        type(rig_t), intent(out) :: rg
        type(start_t), intent(out) :: st
        real(dp), intent(out) :: t0
        integer :: j
        rg = prob%rg
        st = prob%st
        t0 = prob%t0
        do j = 1, prob%np
            select case (prob%which(j))
            case (P_I1)
                rg%inertia(1) = p(j)
            case (P_CV)
                rg%c_v = p(j)
            case (P_CQ)
                rg%c_q = p(j)
            case (P_AMP)
                st%amplitude = p(j)
            case default
                t0 = p(j)
            end select
        end do
    end subroutine apply_parameters

    !> Residuals (model - measured)/u_i over the first nuse samples.  A parameter set the
    !! model cannot take (I1 <= 0, an amplitude outside 0 .. 180 degrees, a cable slack, ...)
    !! is a failed evaluation.
    subroutine record_residual(prob, p, r, stat)
        class(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        type(rig_t) :: rg
        type(start_t) :: st
        real(dp) :: t0
        real(dp), allocatable :: vals(:)
        call apply_parameters(prob, p, rg, st, t0)
        r = 0.0_dp
        if (.not. (rg%inertia(1) > 0.0_dp) .or. .not. (st%amplitude > 0.0_dp .and. &
            st%amplitude < 180.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'parameters out of the model''s range')
            return
        end if
        allocate (vals(prob%nuse))
        call record_model(rg, st, prob%acc, prob%rec%t(1:prob%nuse), t0, prob%rate, vals, stat)
        if (stat%code /= 0) return
        r = (vals - prob%rec%v(1:prob%nuse))*prob%w(1:prob%nuse)
        if (.not. all_finite(r)) call set_error(stat, ERR_NUMERIC, 'non-finite model values')
    end subroutine record_residual

    !> The record fit of a deck: the problem (estimated parameters, start values,
    !! difference steps) from the deck and the record.
    subroutine fit_problem(d, rec, prob, p0, h)
        type(deck_t), intent(in) :: d
        type(record_t), intent(in) :: rec
        type(record_fit_t), intent(out) :: prob
        real(dp), allocatable, intent(out) :: p0(:), h(:)
        real(dp) :: tp
        integer :: j, k
        prob%rg = rig_of(d)
        prob%st = start_of(d)
        prob%acc = accuracy_of(d)
        prob%seed = d%seed
        prob%rec = rec
        prob%rate = trim(d%quantity) == 'rate'
        prob%t0 = 0.0_dp
        prob%nuse = size(rec%t)
        prob%w = 1.0_dp/rec%u
        prob%np = 0
        do k = 1, 5
            if (estimated(d, PARAM_NAMES(k))) then
                prob%np = prob%np + 1
                prob%which(prob%np) = k
            end if
        end do
        allocate (p0(prob%np), h(prob%np))
        tp = mean_period(rec)
        if (.not. (tp > 0.0_dp)) tp = rec%t(size(rec%t)) - rec%t(1)
        do j = 1, prob%np
            select case (prob%which(j))
            case (P_I1)
                p0(j) = d%inertia(1)
                h(j) = H_REL*d%inertia(1)
            case (P_CV)
                p0(j) = d%c_v
                h(j) = H_REL*max(d%c_v, DAMP_REF*d%mass*d%b_prime*sqrt(d%g*d%b_prime))
            case (P_CQ)
                p0(j) = d%c_q
                h(j) = H_REL*max(d%c_q, DAMP_REF*d%mass*d%b_prime**2)
            case (P_AMP)
                p0(j) = d%amplitude
                h(j) = H_REL*max(d%amplitude, 1.0_dp)
            case default
                p0(j) = 0.0_dp
                h(j) = H_REL*tp
            end select
        end do
    end subroutine fit_problem

    !> Fit the record by Levenberg-Marquardt on growing windows (about two mean periods of
    !! the record, then twice as long each time, then the whole record), each from the
    !! last estimate.  res: the last fit (whole record); iterations summed over windows.
    subroutine fit_record(prob, p0, h, res, stat)
        type(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p0(:), h(:)
        type(lsq_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: part
        real(dp) :: tp, span, win
        real(dp), allocatable :: p(:)
        integer :: n, iters, evals
        n = size(prob%rec%t)
        tp = mean_period(prob%rec)
        span = prob%rec%t(n) - prob%rec%t(1)
        p = p0
        iters = 0
        evals = 0
        win = 2.0_dp*tp
        if (.not. (tp > 0.0_dp)) win = 2.0_dp*span
        do
            prob%nuse = n
            if (win < span) prob%nuse = max(count(prob%rec%t <= prob%rec%t(1) + win), &
                                            2*prob%np + 2)
            if (prob%nuse >= n) exit
            opts%xtol = 1.0e-6_dp
            opts%chi2_tol = 1.0_dp
            call lm_fit(prob, p, h, prob%nuse, opts, part, stat)
            iters = iters + part%iterations
            evals = evals + part%evaluations
            if (stat%code /= 0) then
                stat%msg = 'the fit on the first '//itoa(prob%nuse)//' samples: '//stat%msg
                res = part
                res%iterations = iters
                res%evaluations = evals
                return
            end if
            p = part%p
            win = 2.0_dp*win
        end do
        prob%nuse = n
        opts = lsq_options_t()
        call lm_fit(prob, p, h, n, opts, res, stat)
        res%iterations = res%iterations + iters
        res%evaluations = res%evaluations + evals
    end subroutine fit_record

    !> A fit that gave no estimate (ERR_NUMERIC, exit 3): the message gets the residual
    !! and what to check.
    subroutine explain_fit_failure(stat, prob, fit)
        type(status_t), intent(inout) :: stat
        type(record_fit_t), intent(in) :: prob
        type(lsq_result_t), intent(in) :: fit
        character(len=:), allocatable :: what
        what = stat%msg
        if (index(what, 'identify: ') == 1) what = what(11:)
        stat%code = ERR_NUMERIC
        stat%msg = 'identify: '//what//' (residual rms '// &
            sci(sqrt(sum((fit%r/prob%w)**2)/max(1, size(fit%r))))// &
            trim(merge(' rad  ', ' rad/s', .not. prob%rate))//'); check the record''s'// &
            ' units (t in s, '//trim(merge('theta4 in rad', 'W in rad/s   ', &
            .not. prob%rate))//') and &measurement quantity, the start (&start '// &
            'amplitude, the release time t0), the rig''s lengths and the start '// &
            'value of I1 (&body inertia(1)), or estimate fewer parameters'
    end subroutine explain_fit_failure

    !> C = s^2 (J^T J)^-1 from the singular values of J with its columns scaled to unit norm
    !! (ERR_NUMERIC naming the parameters when J is rank deficient: the record does not
    !! determine them together).
    subroutine covariance(jac, s2, cov, stat)
        real(dp), intent(in) :: jac(:, :)
        real(dp), intent(in) :: s2
        real(dp), allocatable, intent(out) :: cov(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: cn(size(jac, 2)), js(size(jac, 1), size(jac, 2)), sv(size(jac, 2))
        real(dp) :: vt(size(jac, 2), size(jac, 2))
        integer :: n, i, j
        n = size(jac, 2)
        allocate (cov(n, n))
        cov = 0.0_dp
        do j = 1, n
            cn(j) = norm2(jac(:, j))
            if (.not. (cn(j) > 0.0_dp)) then
                call set_error(stat, ERR_NUMERIC, 'identify: the record does not depend on '// &
                    'parameter '//itoa(j)//' of &measurement estimate; estimate fewer parameters')
                return
            end if
            js(:, j) = jac(:, j)/cn(j)
        end do
        call la_svd(js, sv, vt, stat)
        if (stat%code /= 0) return
        if (sv(n) < sv(1)/COND_MAX) then
            call set_error(stat, ERR_NUMERIC, 'identify: the record does not determine the '// &
                'estimated parameters together (condition number '//sci(sv(1)/sv(n), 1)// &
                '); estimate fewer parameters or use a longer record')
            return
        end if
        do j = 1, n
            do i = 1, n
                cov(i, j) = s2*sum(vt(:, i)*vt(:, j)/sv**2)/(cn(i)*cn(j))
            end do
        end do
    end subroutine covariance

    !> dp/dx_j = -(J^T J)^-1 J^T dr/dx_j at the estimate (dr/dx by central differences with
    !! a relative step H_REL; the weights are in J and r).
    subroutine input_sensitivity(prob, p, jac, j, x, dpdx, stat)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: p(:), jac(:, :)
        integer, intent(in) :: j                !! input: 1 mass .. 6 g, 7 amplitude
        real(dp), intent(in) :: x               !! its value
        real(dp), intent(out) :: dpdx(:)
        type(status_t), intent(out) :: stat
        type(record_fit_t) :: pp, pm
        real(dp) :: hx, rp(size(jac, 1)), rm(size(jac, 1))
        hx = H_REL*abs(x)
        pp = prob
        pm = prob
        call set_input(pp%rg, pp%st, j, x + hx)
        call set_input(pm%rg, pm%st, j, x - hx)
        call pp%residual(p, rp, stat)
        if (stat%code /= 0) return
        call pm%residual(p, rm, stat)
        if (stat%code /= 0) return
        call la_lstsq(jac, (rp - rm)/(2.0_dp*hx), dpdx, stat)
        dpdx = -dpdx
    end subroutine input_sensitivity

    !> Set input j of an uncertainty budget (1 mass, 2 l, 3 l_prime, 4 b, 5 b_prime (both
    !! body attachment points move, move_b_prime), 6 g, 7 the start amplitude) to v.
    subroutine set_input(rg, st, j, v)
        type(rig_t), intent(inout) :: rg
        type(start_t), intent(inout) :: st
        integer, intent(in) :: j
        real(dp), intent(in) :: v
        select case (j)
        case (1)
            rg%mass = v
        case (2)
            rg%l = v
        case (3)
            rg%l_prime = v
        case (4)
            rg%b = v
        case (5)
            call move_b_prime(rg, v)
        case (6)
            rg%g = v
        case default
            st%amplitude = v
        end select
    end subroutine set_input

    !> The inputs of a record fit's budget and Monte Carlo: mass, l, l_prime, b, b_prime,
    !! g, and the start amplitude when it is held (not estimated, &start mode 'raised'):
    !! their names, values and standard uncertainties (in the order of set_input).
    subroutine budget_inputs(d, xname, xval, ux)
        type(deck_t), intent(in) :: d
        character(len=16), allocatable, intent(out) :: xname(:)
        real(dp), allocatable, intent(out) :: xval(:), ux(:)
        xname = [character(len=16) :: 'mass', 'l', 'l_prime', 'b', 'b_prime', 'g']
        xval = [d%mass, d%l, d%l_prime, d%b, d%b_prime, d%g]
        ux = [d%u_mass, d%u_l, d%u_l_prime, d%u_b, d%u_b_prime, d%u_g]
        if (.not. estimated(d, 'amplitude') .and. trim(d%mode) == 'raised') then
            xname = [xname, [character(len=16) :: 'amplitude']]
            xval = [xval, d%amplitude]
            ux = [ux, d%u_amplitude]
        end if
    end subroutine budget_inputs

    !> The samples of a record fit's Monte Carlo from the deck, its record and the payload
    !! of record_monte_carlo (the task rank 0 runs and the other ranks build).
    subroutine record_mc_task(d, rec, payload, task)
        type(deck_t), intent(in) :: d
        type(record_t), intent(in) :: rec
        real(dp), intent(in) :: payload(:)      !! crc (2), sigma, np, phat, u_p, jac
        type(record_mc_task_t), intent(out) :: task
        real(dp), allocatable :: p0(:), h(:)
        character(len=16), allocatable :: xname(:)
        integer :: np, m
        call fit_problem(d, rec, task%prob, p0, h)
        call budget_inputs(d, xname, task%xval, task%ux)
        m = size(rec%t)
        task%sigma = payload(3)
        np = nint(payload(4))
        task%phat = payload(5:4 + np)
        task%u_p = payload(5 + np:4 + 2*np)
        task%jac = reshape(payload(5 + 2*np:4 + 2*np + m*np), [m, np])
        task%nest = np
    end subroutine record_mc_task

    !> Monte Carlo sample k of a record fit: inputs and measured values drawn from stream k
    !! of the seed, then the refit from the estimate; est: the sample's parameters (I1
    !! first).  A failed refit: ERR_NUMERIC naming the sample.
    subroutine record_mc_point(self, k, est, stat)
        class(record_mc_task_t), intent(in) :: self
        integer, intent(in) :: k                !! sample number
        real(dp), intent(out) :: est(:)         !! the sample's parameters
        type(status_t), intent(out) :: stat
        type(record_fit_t) :: q
        type(rng_t) :: g
        type(lsq_result_t) :: fit
        real(dp) :: p(size(self%phat)), dp_(size(self%phat)), r(size(self%jac, 1))
        real(dp) :: h(size(self%phat))
        integer :: j, it
        logical :: done
        est = 0.0_dp
        g = rng_stream(self%prob%seed, k)
        q = self%prob
        do j = 1, size(self%xval)
            call set_input(q%rg, q%st, j, self%xval(j) + self%ux(j)*rng_normal(g))
        end do
        do j = 1, size(q%rec%v)
            if (self%prob%rec%has_u) then
                q%rec%v(j) = self%prob%rec%v(j) + self%prob%rec%u(j)*rng_normal(g)
            else
                q%rec%v(j) = self%prob%rec%v(j) + self%sigma*rng_normal(g)
            end if
        end do
        ! Gauss-Newton with the estimate's Jacobian
        p = self%phat
        done = .false.
        do it = 1, 8
            call q%residual(p, r, stat)
            if (stat%code /= 0) exit
            call la_lstsq(self%jac, -r, dp_, stat)
            if (stat%code /= 0) exit
            p = p + dp_
            if (all(abs(dp_) <= 1.0e-3_dp*self%u_p + 1.0e-14_dp*abs(p))) then
                done = .true.
                exit
            end if
        end do
        if (.not. done) then
            do j = 1, size(p)
                h(j) = H_REL*max(abs(self%phat(j)), self%u_p(j))
            end do
            call lm_fit(q, self%phat, h, size(r), lsq_options_t(), fit, stat)
            if (stat%code /= 0) then
                stat%code = ERR_NUMERIC
                stat%msg = 'Monte Carlo sample '//itoa(k)//': '//stat%msg
                return
            end if
            p = fit%p
        end if
        stat%code = 0
        est = p
    end subroutine record_mc_point

    !> A record made by the program itself: the deck's rig (with its &damping) released
    !! from &start, sampled every 1/rate_hz s from 0 to duration (s), theta4 (quantity
    !! 'angle', rad) or W (quantity 'rate', rad/s) with seeded normal noise of standard
    !! deviation sigma (stream 0 of seed), written to path (t with 6 decimals, the value with
    !! 10 significant digits: the noise is far above both, and the text repeats exactly).
    subroutine make_record(d, duration, rate_hz, sigma, seed, quantity, path, stat)
        type(deck_t), intent(in) :: d           !! the true rig (simulate deck)
        real(dp), intent(in) :: duration, rate_hz, sigma   !! s, Hz, record units
        integer, intent(in) :: seed
        character(len=*), intent(in) :: quantity    !! 'angle' or 'rate'
        character(len=*), intent(in) :: path
        type(status_t), intent(out) :: stat
        type(out_files_t) :: files
        type(rng_t) :: g
        real(dp), allocatable :: t(:), v(:)
        integer :: n, i, u, ios
        character(len=64) :: line
        n = nint(duration*rate_hz)
        allocate (t(0:n), v(0:n))
        do i = 0, n
            t(i) = i/rate_hz
        end do
        call record_model(rig_of(d), start_of(d), accuracy_of(d), t, 0.0_dp, quantity == 'rate', &
                          v, stat)
        if (stat%code /= 0) return
        g = rng_stream(seed, 0)
        do i = 0, n
            v(i) = v(i) + sigma*rng_normal(g)
        end do
        call files%open(path, u, stat)
        if (stat%code /= 0) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar make_record: '//trim(d%title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# simulated from '//d%path// &
            ' (&damping c_v = '//sci(d%c_v, 6)//', c_q = '//sci(d%c_q, 6)//', I1 = '// &
            sci(d%inertia(1), 6)//'), noise sigma = '//sci(sigma, 3)//', seed '//itoa(seed)
        if (ios == 0) write (u, '(a)', iostat=ios) '# t (s from release)  '// &
            trim(merge('theta4 (rad)', 'W (rad/s)   ', quantity == 'angle'))
        do i = 0, n
            write (line, '(f12.6,es19.9e3)') t(i), v(i)
            if (ios == 0) write (u, '(a)', iostat=ios) trim(line)
        end do
        call files%close(u, ios, stat)
        if (stat%code == 0) call files%commit(stat)
        if (stat%code /= 0) call files%discard()
    end subroutine make_record

end module record_fit
