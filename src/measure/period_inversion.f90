!> The moment of inertia I1 from measured periods of torsion, with its uncertainty.
!!
!! The bifilar rig exists to measure moments of inertia: a period of torsional oscillation
!! is measured and turned into I1, the principal moment about b1, vertical at rest.  The
!! classical formula I1 = m g b b' T^2 / (16 pi^2 l) comes from the linearised equations;
!! here the period is the exact period of pure torsion (eqs. (45)-(49), module floquet's
!! torsion_period: the energy integral of the one-degree-of-freedom motion, for b /= b'
!! too), so amplitude does not bias the result.
!!
!! * Inversion: several periods T_i measured at peak amplitudes A_i (degrees of theta4) are
!!   combined by weighted least squares, min sum w_i (T_i(I1) - T_i^meas)^2, with
!!   w_i = 1/(u_T^2 + (dT_i/dA u_A)^2) (equal weights when no uncertainty is given), solved
!!   by Gauss-Newton in the one unknown (the estimator, module estimator: the residuals
!!   (T_i(I1) - T_i) w_i^(1/2), the step halved), safeguarded to stay at I1 > 0, until the
!!   step is below 1e-14 of I1 or the weighted residuals are orthogonal to the slopes to
!!   1e-7 (the step left below 1e-7 standard errors: the periods' roundoff, about 1e-11 of
!!   a period, is reached first when they scatter); a step no halving makes lower the sum
!!   of squares is convergence when the undamped step is below 1e-11 of I1 (the periods'
!!   roundoff) or the orthogonality test holds.  T(I1) increases
!!   strictly with I1 and tends to a positive limit T_min as I1 -> 0 (the body still rises
!!   as it turns), so a period below T_min is refused: no positive I1 gives it.
!! * First-order uncertainty (GUM, JCGM 100:2008, section 5.1): u(I1)^2 = sum_j (c_j u_j)^2
!!   over the independent inputs (mass, l, l', b, b', g, each period, each amplitude), with
!!   the sensitivities c_j = dI1/dx_j by central differences of the whole inversion.  Pure
!!   torsion needs l = l'; the rig is then mirror-symmetric, T(l, l') = T(l', l), so to
!!   first order dI1/dl = dI1/dl' = (1/2) dI1/dL with L the common length.  A change of b'
!!   moves the two body attachment points symmetrically: the mass centre keeps its depth
!!   below, and its offset along, the midpoint of CD (r and lambda follow).
!! * Monte Carlo (GUM Supplement 1, JCGM 101:2008): sample k draws every input from its
!!   normal distribution with the k-th stream of the seed (module random) and inverts again;
!!   u is the standard deviation of the samples.  The two cable lengths are drawn
!!   independently and the period taken at their mean (their difference changes the period
!!   only at second order).  Each sample depends only on (seed, k): any order, thread or
!!   rank gives the same numbers.  The samples are a sweep (module monte_carlo) over the
!!   OpenMP threads and the MPI ranks, checkpointed and resumed like a chart.
!!
!! * A platform of three cables with the body's mass centre off its axis gets its periods
!!   from the platform's own model: the period of its periodic torsion at the amplitude
!!   (module platform_measure), where simulated_period_s is called; on its axis pure
!!   torsion is exact, as on the bifilar with b = 2 radius.
!! * Asymmetric rigs (unequal cables, a mass centre off the vertical bisector of AB: the
!!   rigs where pure torsion is not an exact motion) get their periods from the full model:
!!   the period at amplitude A is the time from release at rest at theta4 = A (&start
!!   mode 'raised' at A, no tilt, no damping) to the next maximum of theta4, the first zero
!!   of theta4' from + to - after theta4 has swung below 0 (simulated_period_s: the run loop
!!   of module run_loop with the deck's rtol and atol, the zero located in the integrator's
!!   dense output).  For a symmetric rig this is the exact torsion period (a test checks it
!!   to 1e-9).  Damping does not enter: a measured period is taken as that of the undamped
!!   rig at its peak amplitude (viscous damping lengthens a period by a factor
!!   1/sqrt(1 - zeta^2), 1 + 5e-7 at zeta = 1e-3).  The budget then varies l and l'
!!   separately and Monte Carlo draws them separately; the difference steps are 1e-4
!!   relative (the simulated period carries the integration error, about rtol), and
!!   Gauss-Newton stops at a relative change of 1e-10.  A trial I1 the model cannot swing
!!   with (a cable slack at release when I1 is very small) counts as a failed step; periods
!!   shorter than the model's down to the smallest I1 it can swing with are refused.
!!
!! * A common amplitude scale (every amplitude read on one instrument's scale, A_i k with
!!   k = 1 as read): with fit_scale, k is a second parameter fitted with I1 from the
!!   period-amplitude relation (periods at several amplitudes), T_i(I1, A_i k); the budget's
!!   inversions fit it too, so each row's sensitivity of I1 is the whole two-parameter fit's,
!!   and dk/dx is kept per row (scale_c) for k's own u.  A scale known to a relative
!!   standard uncertainty u_s (scale_prior = u_s) enters the same fit as one more residual,
!!   (k - 1)/u_s: the periods' residuals are then tested against their u with the scale's
!!   part in them (generalised least squares: the scale is common to every period), and the
!!   budget's row amplitude_scale has dI1/dk, a central difference of the whole inversion
!!   with every amplitude scaled by 1 +- h.  Without u stated for the timings (their
!!   scatter sets it) the scale is not fitted: the row alone carries it.
!!
!! Units are the deck's (consistent units, time in seconds): I1 in mass x length^2,
!! periods in s, amplitudes in degrees.  No routine stops; failures come back in status_t.
module period_inversion
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, ERR_DECK, ERR_NUMERIC
    use text, only: itoa, fixed, sci
    use geometry, only: pendulum_t
    use deck_base, only: deck_source_t
    use rig, only: rig_t, start_t, accuracy_t, make_pendulum, start_state, raised_start, &
        move_b_prime
    use kane_run, only: kane_run_start, kane_run_t
    use floquet, only: check_torsion_scene, torsion_period
    use random, only: rng_t, rng_stream, rng_normal
    use bifilar_model, only: NSTATE
    use run_loop, only: drive
    use theta4_maxima, only: maxima_sink_t
    use output_io, only: out_files_t
    use budget, only: input_u_t, budget_row_t
    use inputs, only: input_t, set_input, no_effect_on_torsion
    use sweep_engine, only: sweep_options_t, sweep_report_t
    use monte_carlo, only: mc_task_t, monte_carlo_run
    use estimator, only: lsq_problem_t, lsq_options_t, lsq_result_t, estimate, DAMP_HALVING, &
        STEP_LARGEST, FAIL_START, FAIL_EVALUATION, FAIL_JACOBIAN
    use budget, only: ROW_INPUT, ROW_TIMING, ROW_AMPLITUDE, ROW_AMPLITUDE_SCALE
    use unused_arg, only: unused
    use platform_measure, only: offaxis_platform, platform_period_s
    implicit none
    private


    !> Result of an inversion of periods.
    type, public :: period_fit_t
        real(dp) :: i1 = 0.0_dp                 !! estimate of I1 (deck units)
        real(dp) :: u_i1 = 0.0_dp               !! first-order standard uncertainty (budget)
        real(dp) :: residual_rms = 0.0_dp       !! rms of T(I1) - T measured (s)
        integer :: iterations = 0               !! Gauss-Newton iterations
        real(dp), allocatable :: model_periods(:)   !! T_i(I1) (s)
        type(budget_row_t), allocatable :: budget(:)
        !> The self-check of the estimator (periods with stated u): tested (the u stated),
        !! consistent (chi^2's p >= 0.05), chi^2, dof, p, the Birge ratio, inflation =
        !! max(1, Birge) when inconsistent (else 1), worst: the period with the largest
        !! normalised residual, z_worst that residual over its u.
        logical :: tested = .false., consistent = .true.
        real(dp) :: chi2 = 0.0_dp, p_value = 1.0_dp, birge = 0.0_dp, inflation = 1.0_dp
        real(dp) :: z_worst = 0.0_dp
        integer :: dof = 0, worst = 0
        !> with fit_scale: the amplitudes' scale k fitted (A_i k), its u from the fit alone,
        !! and (period_budget) dk/dx of each budget row, in the rows' order
        logical :: scaled = .false.
        real(dp) :: scale = 1.0_dp, u_scale_fit = 0.0_dp
        real(dp), allocatable :: scale_c(:)
    end type period_fit_t

    public :: input_u_t, budget_row_t
    public :: torsion_period_s, invert_periods, period_budget, period_mc_sample
    public :: period_monte_carlo, linear_inertia, rig_period_s, simulated_period_s
    public :: is_torsion_rig, period_mc_payload, period_mc_task

    !> The samples of a Monte Carlo of periods (period_mc_sample) as a sweep; built by
    !! period_mc_task from the rig and the payload.
    type, extends(mc_task_t), public :: period_mc_task_t
        type(rig_t) :: rg                       !! the rig
        type(accuracy_t) :: acc                 !! its runs' accuracy (simulated periods)
        real(dp), allocatable :: periods(:), amps(:)    !! measurements (s, degrees)
        real(dp), allocatable :: cycles(:)      !! the cycles each period's time spans
        type(input_u_t) :: u                    !! standard uncertainties
        type(input_t), allocatable :: x(:)      !! the rig's inputs (module inputs)
        real(dp) :: i1_start = 0.0_dp           !! start of each inversion
        integer :: seed = 1
    contains
        procedure :: sample => period_mc_point
    end type period_mc_task_t

    !> The inversion of periods as a least-squares problem of the estimator: the weighted
    !! residuals of the one parameter I1 (period_residual), the slope by a forward
    !! difference (period_jacobian).
    type, extends(lsq_problem_t) :: period_problem_t
        type(rig_t) :: rg                       !! the rig
        type(accuracy_t) :: acc                 !! simulated periods' accuracy
        logical :: sym = .true.                 !! exact torsion (else simulated periods)
        real(dp), allocatable :: periods(:), amps(:)    !! measured (s, degrees)
        real(dp), allocatable :: sw(:)          !! the weights' roots (1/u)
        real(dp), allocatable :: tm(:)          !! the model's periods at I1 = i1_last
        real(dp) :: i1_last = -huge(1.0_dp)
        logical :: fit_scale = .false.         !! p(2): the amplitudes' scale k
        real(dp) :: k_last = -huge(1.0_dp)      !! the k of tm
        real(dp) :: prior = 0.0_dp              !! > 0: k's relative u, the residual (k - 1)/prior
    contains
        procedure :: residual => period_residual
        procedure :: nres => period_nres
        procedure :: jacobian => period_jacobian
    end type period_problem_t

    integer, parameter :: MAX_ITER = 60         !! Gauss-Newton iterations (Jacobians)
    !> Gauss-Newton has converged when the weighted residuals are orthogonal to the slopes
    !! to this (the cosine of their angle): the step left is below GRAD_TOL standard errors.
    real(dp), parameter :: GRAD_TOL = 1.0e-7_dp
    real(dp), parameter :: I_TOL = 1.0e-14_dp   !! relative change of I1 that ends them
    real(dp), parameter :: FD_REL = 1.0e-6_dp   !! relative step of the sensitivities
    real(dp), parameter :: I_TINY = 1.0e-9_dp   !! I1 -> 0 limit, over m b'^2
    !> Asymmetric rigs (simulated periods): smallest I1 (the deck's smallest moment, over
    !! m b'^2), relative step of the budget's differences, relative change that ends
    !! Gauss-Newton, relative step of its slopes.
    real(dp), parameter :: I_TINY_SIM = 1.0e-6_dp, FD_REL_SIM = 1.0e-4_dp
    real(dp), parameter :: I_TOL_SIM = 1.0e-10_dp, SLOPE_REL_SIM = 1.0e-5_dp
    !> Most periods (of the small-amplitude estimate) a simulated period may take.
    real(dp), parameter :: PERIODS_MAX = 20.0_dp

contains

    !> The exact period (s) of pure torsion of the deck's rig with I1 = i1 at peak
    !! amplitude amp_deg.  ERR_DECK when the rig is not a torsion scene (equal cables, mass
    !! centre below the midpoint of CD, b1 vertical at rest) or the cables cannot reach.
    subroutine torsion_period_s(rg, i1, amp_deg, t, stat)
        type(rig_t), intent(in) :: rg           !! the rig (deck units)
        real(dp), intent(in) :: i1              !! principal moment about b1 (deck units)
        real(dp), intent(in) :: amp_deg         !! peak amplitude of theta4 (degrees)
        real(dp), intent(out) :: t              !! period (s)
        type(status_t), intent(out) :: stat
        type(pendulum_t) :: p
        call torsion_pendulum(rg, i1, p, stat)
        t = 0.0_dp
        if (stat%code /= 0) return
        call scaled_period(rg, p, amp_deg, t, stat)
    end subroutine torsion_period_s

    !> True when the deck's rig is a torsion scene (equal cables, mass centre on the
    !! vertical bisector of AB, a principal axis vertical at rest): its periods are then
    !! those of pure torsion; else they are simulated.
    logical function is_torsion_rig(rg)
        type(rig_t), intent(in) :: rg           !! the rig
        type(pendulum_t) :: p
        type(status_t) :: st
        integer :: ivert
        is_torsion_rig = .false.
        if (offaxis_platform(rg)) return
        call make_pendulum(rg, p, st)
        if (st%code /= 0) return
        call check_torsion_scene(p, ivert, st)
        is_torsion_rig = st%code == 0
    end function is_torsion_rig

    !> The period (s) of the deck's rig with I1 = i1 at peak amplitude amp_deg: the exact
    !! period of pure torsion (torsion_period_s) on a torsion scene, else the period of the
    !! full model (simulated_period_s).
    subroutine rig_period_s(rg, acc, i1, amp_deg, t, stat)
        type(rig_t), intent(in) :: rg           !! the rig
        type(accuracy_t), intent(in) :: acc     !! accuracy of a simulated period
        real(dp), intent(in) :: i1              !! principal moment about b1 (deck units)
        real(dp), intent(in) :: amp_deg         !! peak amplitude of theta4 (degrees)
        real(dp), intent(out) :: t              !! period (s)
        type(status_t), intent(out) :: stat
        if (is_torsion_rig(rg)) then
            call torsion_period_s(rg, i1, amp_deg, t, stat)
        else
            call simulated_period_s(rg, acc, i1, amp_deg, t, stat)
        end if
    end subroutine rig_period_s

    !> The period (s) of the full model (any rig) with I1 = i1: the time from release at
    !! rest at theta4 = amp_deg (&start mode 'raised' at that amplitude, no tilt, no
    !! damping) to the next maximum of theta4 (see the module header).  Integrated with the
    !! accuracy acc (the deck's rtol, atol and integrator), in memory, through the run loop.
    subroutine simulated_period_s(rg, acc, i1, amp_deg, t, stat)
        type(rig_t), intent(in) :: rg           !! the rig
        type(accuracy_t), intent(in) :: acc     !! rtol, atol, integrator
        real(dp), intent(in) :: i1              !! principal moment about b1 (deck units)
        real(dp), intent(in) :: amp_deg         !! peak amplitude of theta4 (degrees)
        real(dp), intent(out) :: t              !! period (s)
        type(status_t), intent(out) :: stat
        type(rig_t) :: rr
        type(pendulum_t) :: p
        type(kane_run_t) :: m
        type(maxima_sink_t) :: sink
        real(dp) :: y0(NSTATE), th0(5), t_end, jz
        t = 0.0_dp
        if (offaxis_platform(rg)) then
            ! a platform's body off its axis: the platform's own periodic torsion
            call platform_period_s(rg, acc, i1, amp_deg, t, stat)
            return
        end if
        rr = rg
        rr%inertia(1) = i1
        rr%c_v = 0.0_dp
        rr%c_q = 0.0_dp
        call make_pendulum(rr, p, stat)
        if (stat%code /= 0) return
        call start_state(raised_start(amp_deg), p, y0, th0, stat)
        if (stat%code /= 0) return
        ! an end well beyond the period: PERIODS_MAX small-amplitude periods of the body
        ! turning about the vertical through its mass centre's offset from O, or about O
        jz = p%inertia(1) + p%r**2 + 0.25_dp
        t_end = PERIODS_MAX*4.0_dp*pi*sqrt(jz*p%big_l/p%big_b)
        call kane_run_start(m, p, y0, th0(3), acc%rtol, acc%atol, acc%method, t_end, &
                            'raise &integration rtol/atol', stat)
        if (stat%code /= 0) return
        sink%watch_steps = .true.
        call drive(m, [0.0_dp, t_end], sink, stat)
        if (stat%code /= 0) then
            stat%msg = 'the period at '//fixed(amp_deg, 3)//' deg (simulated): '//stat%msg
            return
        end if
        if (sink%found < 1) then
            call set_error(stat, ERR_NUMERIC, 'the period at '//fixed(amp_deg, 3)//' deg '// &
                '(simulated): theta4 reached no maximum after its first swing within '// &
                'tau = '//fixed(t_end, 3)//'; the rig does not swing in torsion')
            return
        end if
        t = sink%t(1)*sqrt(rg%b_prime/rg%g)
    end subroutine simulated_period_s

    !> Scaled parameters of the rig with I1 = i1, checked to be a torsion scene with b1
    !! vertical at rest.
    subroutine torsion_pendulum(rg, i1, p, stat)
        type(rig_t), intent(in) :: rg
        real(dp), intent(in) :: i1
        type(pendulum_t), intent(out) :: p
        type(status_t), intent(out) :: stat
        type(rig_t) :: rr
        integer :: ivert
        rr = rg
        rr%inertia(1) = i1
        call make_pendulum(rr, p, stat)
        if (stat%code /= 0) return
        call check_torsion_scene(p, ivert, stat)
        if (stat%code /= 0) return
        if (ivert /= 1) call set_error(stat, ERR_DECK, '&body btilde: b1 is not vertical at '// &
            'rest: the period of torsion does not depend on I1; allowed: row 1 of btilde '// &
            '(+-1, 0, 0) for identify')
    end subroutine torsion_pendulum

    !> Period in seconds of the scaled pendulum p (period in tau over sqrt(g/b')).
    subroutine scaled_period(rg, p, amp_deg, t, stat)
        type(rig_t), intent(in) :: rg
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: amp_deg
        real(dp), intent(out) :: t
        type(status_t), intent(out) :: stat
        call torsion_period(p, amp_deg*deg, 1, t, stat)
        t = t*sqrt(rg%b_prime/rg%g)
    end subroutine scaled_period

    !> I1 by weighted least squares from periods (s) measured at peak amplitudes (degrees).
    !! Starts from rg%inertia(1).  ERR_DECK for a period no positive I1 can give (or not a
    !! torsion scene); ERR_NUMERIC when Gauss-Newton does not converge.  timing_weights:
    !! the weights from the timings' u alone (u_each, known to a common factor: timings whose
    !! u is their scatter, found after the fit), not from the amplitudes'.  fit_scale: the
    !! amplitudes' common scale k fitted too (module header), from k_start (else 1), with
    !! scale_prior > 0 its relative u as read (one more residual).
    subroutine invert_periods(rg, acc, periods, amps, u, fit, stat, u_each, timing_weights, &
                              fit_scale, k_start, scale_prior)
        type(rig_t), intent(in) :: rg           !! the rig; inertia(1) is the start guess
        type(accuracy_t), intent(in) :: acc     !! accuracy of simulated periods
        real(dp), intent(in) :: periods(:)      !! measured full periods (s)
        real(dp), intent(in) :: amps(:)         !! their peak amplitudes (degrees)
        type(input_u_t), intent(in) :: u        !! uncertainties (weights from period, amplitude)
        type(period_fit_t), intent(out) :: fit
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: u_each(:) !! each period's u (s), else u%period
        logical, intent(in), optional :: timing_weights !! weights from u_each alone
        logical, intent(in), optional :: fit_scale      !! fit the amplitudes' scale k too
        real(dp), intent(in), optional :: k_start       !! its start (1: as read)
        real(dp), intent(in), optional :: scale_prior   !! k's relative u (0: k free)
        type(period_problem_t) :: prob
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        real(dp) :: w(size(periods)), up(size(periods))
        real(dp) :: scale, i1, ilo, tmin, ta, tb, h, dtda, k0
        real(dp), allocatable :: p0(:), rr(:)
        integer :: i, n
        character(len=300) :: buf
        logical :: sym, amp_w
        stat%code = 0
        allocate (fit%model_periods(size(periods)))
        fit%model_periods = 0.0_dp
        if (size(periods) < 1 .or. size(amps) /= size(periods)) then
            call set_error(stat, ERR_DECK, '&measurement periods, amplitudes: not one '// &
                'amplitude per period; allowed: at least one period, one amplitude each')
            return
        end if
        scale = rg%mass*rg%b_prime**2
        sym = is_torsion_rig(rg)
        ilo = merge(I_TINY, I_TINY_SIM, sym)*scale
        ! feasibility: T(I1) > T(0+) for every period (asymmetric rigs: see below); weights
        ! from the amplitudes' effect
        do i = 1, size(periods)
            if (.not. sym) exit
            call model_period(rg, acc, sym, ilo, amps(i), tmin, stat)
            if (stat%code /= 0) return
            if (.not. (periods(i) > tmin)) then
                call set_error(stat, ERR_DECK, '&measurement periods('//itoa(i)//') = '// &
                    sci(periods(i), 5)//' s: shorter than the period of this rig with I1 -> 0 ('// &
                    sci(tmin, 5)//' s at '//fixed(amps(i), 3)//' deg); no positive I1 gives '// &
                    'it: check the units (s), the amplitude and the suspension lengths; '// &
                    'allowed: periods above '//sci(tmin, 5)//' s at that amplitude')
                return
            end if
        end do
        i1 = rg%inertia(1)
        if (.not. (i1 > ilo)) i1 = scale
        w = 1.0_dp
        up = u%period
        if (present(u_each)) up = u_each
        amp_w = u%amplitude > 0.0_dp
        if (present(timing_weights)) amp_w = amp_w .and. .not. timing_weights
        if (any(up > 0.0_dp) .or. amp_w) then
            do i = 1, size(periods)
                dtda = 0.0_dp
                if (amp_w) then
                    ! dT/dA by a difference that stays inside 0 < A < 180 degrees (a step
                    ! past 180 gave a NaN period and a weight of 1/tiny)
                    h = 1.0e-4_dp*max(1.0_dp, amps(i))
                    h = min(h, 0.5_dp*amps(i), 0.5_dp*(180.0_dp - amps(i)))
                    call model_period(rg, acc, sym, i1, amps(i) + h, ta, stat)
                    if (stat%code == 0) call model_period(rg, acc, sym, i1, amps(i) - h, tb, stat)
                    if (stat%code /= 0) return
                    dtda = (ta - tb)/(2*h)
                end if
                w(i) = 1.0_dp/max(tiny(1.0_dp), up(i)**2 + (dtda*u%amplitude)**2)
                if (.not. (w(i) < huge(1.0_dp))) w(i) = 1.0_dp
            end do
            ! weights relative to the largest when huge: their scale does not matter, their
            ! overflow in w g^2 would (a period with no u beside others with)
            if (maxval(w) > 1.0e100_dp) w = w/maxval(w)
        end if
        prob%rg = rg
        prob%acc = acc
        prob%sym = sym
        prob%periods = periods
        prob%amps = amps
        prob%sw = sqrt(w)
        allocate (prob%tm(size(periods)))
        prob%fit_scale = .false.
        if (present(fit_scale)) prob%fit_scale = fit_scale
        k0 = 1.0_dp
        if (present(k_start)) k0 = k_start
        prob%prior = 0.0_dp
        if (present(scale_prior) .and. prob%fit_scale) prob%prior = max(0.0_dp, scale_prior)
        n = size(periods)
        ! Gauss-Newton in I1 (the estimator), the step halved to keep I1 > ilo and to lower
        ! the weighted sum of squares (a simulated period the model cannot give, e.g. a
        ! cable slack at release when I1 is very small, is a failed step too); converged
        ! when the step is below I_TOL of I1, or the weighted residuals are orthogonal to
        ! the slopes to GRAD_TOL (the step left below GRAD_TOL standard errors: the periods'
        ! own roundoff, about 1e-11 of a period, keeps it from I_TOL), or, when no halving
        ! lowers the sum, when the undamped step is at the level of the periods' own error
        ! (simulated: the integration's)
        opts%damping = DAMP_HALVING
        opts%lambda_max = 2.0e18_dp             ! 61 tries: the step down to 2^-60 of itself
        opts%max_iter = huge(1)
        opts%max_jacobians = MAX_ITER
        opts%gtol = 0.0_dp
        opts%otol = GRAD_TOL
        opts%xtol = merge(I_TOL, I_TOL_SIM, sym)
        opts%step_norm = STEP_LARGEST
        opts%ftol = 0.0_dp
        opts%small_gain = huge(1.0_dp)
        opts%floor_gain = 0.0_dp
        opts%exact = 0.0_dp
        opts%floor_xtol = merge(1.0e3_dp*I_TOL, 100.0_dp*I_TOL_SIM, sym)
        opts%fail_on_error = sym
        if (prob%fit_scale) then
            ! k inside (0, 180 deg over the largest amplitude): every swing below 180 deg
            opts%lower = [ilo, 1.0e-3_dp]
            opts%upper = [huge(1.0_dp), (1.0_dp - 1.0e-9_dp)*180.0_dp/maxval(amps)]
            opts%names = [character(len=16) :: 'I1', 'amplitude_scale']
            p0 = [i1, k0]
        else
            opts%lower = [ilo]
            opts%names = [character(len=16) :: 'I1']
            p0 = [i1]
        end if
        ! the self-check (the estimator's): tested when each period's u is stated
        opts%covariance = any(up > 0.0_dp) .or. amp_w .or. prob%fit_scale
        opts%u_stated = .true.
        if (present(timing_weights)) opts%u_stated = .not. timing_weights
        call estimate(prob, p0, opts, res, stat)
        fit%iterations = res%jacobians
        if (res%converged) then
            fit%i1 = res%p(1)
            if (prob%fit_scale) then
                fit%scaled = .true.
                fit%scale = res%p(2)
                if (allocated(res%cov_fit)) fit%u_scale_fit = sqrt(max(0.0_dp, res%cov_fit(2, 2)))
                if (.not. allocated(res%cov_fit)) then
                    ! I1 and the scale not told apart by these periods
                    call set_error(stat, ERR_DECK, '&measurement estimate = ''I1 '// &
                        'amplitude_scale'': the periods do not tell the amplitudes'' scale '// &
                        'from I1; allowed: periods timed at amplitudes far apart (e.g. 10 '// &
                        'and 40 degrees), or u_amplitude_scale instead')
                    return
                end if
            end if
            fit%tested = opts%covariance .and. opts%u_stated .and. res%dof > 0
            fit%dof = res%dof
            fit%chi2 = res%cost
            fit%birge = res%birge
            if (fit%tested) then
                fit%p_value = res%p_value
                fit%consistent = res%consistent
                fit%inflation = res%inflation
                ! the worst period (the scale's own residual is not a period)
                if (size(res%r) > n) fit%worst = maxloc(abs(res%r(1:n)), 1)
                if (size(res%r) <= n) fit%worst = res%worst
                if (fit%worst > 0) fit%z_worst = res%r(fit%worst)
            end if
            ! the model's periods at the estimate (the last evaluation may be a step refused)
            allocate (rr(prob%nres()))
            if (.not. (prob%i1_last == fit%i1 .and. prob%k_last == fit%scale)) &
                call prob%residual(res%p, rr, stat)
            if (stat%code /= 0) return
            fit%model_periods = prob%tm
            fit%residual_rms = sqrt(sum((prob%tm - periods)**2)/size(periods))
            return
        end if
        select case (res%ended)
        case (FAIL_START, FAIL_EVALUATION)
            return
        case (FAIL_JACOBIAN)
            if (sym) return
        end select
        i1 = res%p(1)
        if (.not. sym .and. all(res%r(1:n) > 0.0_dp)) then
            ! the model's periods are all still longer at the smallest I1 the model could
            ! swing with (a cable goes slack below it): no I1 gives them
            call set_error(stat, ERR_DECK, '&measurement periods: shorter than the '// &
                'periods of this rig (simulated) down to I1 = '//sci(i1, 5)//' ('// &
                sci(res%r(1)/prob%sw(1) + periods(1), 5)//' s for periods(1)), below which a '// &
                'cable goes slack; no positive I1 gives them: check the units (s), the '// &
                'amplitudes and the suspension lengths; allowed: periods the rig gives for '// &
                'some I1 > 0')
            return
        end if
        write (buf, '(a,i0,a,es12.5)') 'period inversion: Gauss-Newton did not converge in ', &
            fit%iterations, ' iterations (I1 = ', i1
        call set_error(stat, ERR_NUMERIC, trim(buf)//'); check that the periods agree with '// &
            'each other and with the rig')
    end subroutine invert_periods

    !> The period of the rig with I1 = i1 at amplitude a (degrees): exact torsion (sym), or
    !! simulated for an asymmetric rig.
    subroutine model_period(rg, acc, sym, i1, a, tp, st)
        type(rig_t), intent(in) :: rg
        type(accuracy_t), intent(in) :: acc
        logical, intent(in) :: sym
        real(dp), intent(in) :: i1, a
        real(dp), intent(out) :: tp
        type(status_t), intent(out) :: st
        if (sym) then
            call torsion_period_s(rg, i1, a, tp, st)
        else
            call simulated_period_s(rg, acc, i1, a, tp, st)
        end if
    end subroutine model_period

    !> The residuals (T_i(I1) - T_i measured) w_i^(1/2) (w_i: each period's weight, the
    !! inverse of its variance); the model's periods kept (tm at i1_last).
    subroutine period_residual(prob, p, r, stat)
        class(period_problem_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)            !! I1
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        integer :: k
        real(dp) :: ks
        r = 0.0_dp
        prob%i1_last = -huge(1.0_dp)
        ks = 1.0_dp
        if (prob%fit_scale) ks = p(2)
        do k = 1, size(prob%periods)
            call model_period(prob%rg, prob%acc, prob%sym, p(1), prob%amps(k)*ks, prob%tm(k), &
                              stat)
            if (stat%code /= 0) return
        end do
        r(1:size(prob%periods)) = prob%sw*(prob%tm - prob%periods)
        if (prob%prior > 0.0_dp) r(size(r)) = (ks - 1.0_dp)/prob%prior
        prob%i1_last = p(1)
        prob%k_last = ks
    end subroutine period_residual

    !> The number of periods (and the scale's own residual when it has a prior).
    pure integer function period_nres(prob) result(n)
        class(period_problem_t), intent(in) :: prob
        n = size(prob%periods) + merge(1, 0, prob%prior > 0.0_dp)
    end function period_nres

    !> dr/dI1 (and dr/dk with fit_scale) by forward differences from the model's periods at
    !! p (relative step 1e-7; SLOPE_REL_SIM for simulated periods: only the direction of the
    !! step depends on it).
    subroutine period_jacobian(prob, p, r, h, jac, evaluations, stat)
        class(period_problem_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)            !! I1
        real(dp), intent(in) :: r(:)            !! r(p)
        real(dp), intent(in) :: h(:)            !! (not used: the step is relative to I1)
        real(dp), intent(out) :: jac(:, :)
        integer, intent(out) :: evaluations
        type(status_t), intent(out) :: stat
        real(dp) :: tp, hh, rr(size(r)), ks, hk
        integer :: k
        jac = 0.0_dp
        evaluations = 0
        ks = 1.0_dp
        if (prob%fit_scale) ks = p(2)
        if (.not. (prob%i1_last == p(1) .and. prob%k_last == ks)) then
            call prob%residual(p, rr, stat)
            evaluations = 1
            if (stat%code /= 0) return
        end if
        hh = merge(1.0e-7_dp, SLOPE_REL_SIM, prob%sym)*p(1)
        call unused(h)
        do k = 1, size(prob%periods)
            call model_period(prob%rg, prob%acc, prob%sym, p(1) + hh, prob%amps(k)*ks, tp, &
                              stat)
            if (stat%code /= 0) return
            jac(k, 1) = prob%sw(k)*((tp - prob%tm(k))/hh)
        end do
        evaluations = evaluations + 1
        if (.not. prob%fit_scale) return
        ! dr/dk, the step toward smaller amplitudes (inside 180 degrees); dT/dk is a small
        ! part of T (the amplitude's correction), so the step is larger than I1's
        hk = -1.0e-5_dp*ks
        if (prob%prior > 0.0_dp) jac(size(r), 2) = 1.0_dp/prob%prior
        do k = 1, size(prob%periods)
            call model_period(prob%rg, prob%acc, prob%sym, p(1), prob%amps(k)*(ks + hk), tp, &
                              stat)
            if (stat%code /= 0) return
            jac(k, 2) = prob%sw(k)*((tp - prob%tm(k))/hk)
        end do
        evaluations = evaluations + 1
    end subroutine period_jacobian

    !> First-order (GUM) budget of an inversion: fills fit%budget and fit%u_i1.  Rows: the
    !! rig's inputs (x when given, with their names of module inputs; else mass, l, l_prime,
    !! b, b_prime, g with the uncertainties of u), then period(i) and amplitude(i) for each
    !! period; an input of u = 0 is left out (nothing to propagate, and no step to take).
    !! The sensitivities are central differences of the whole inversion (relative step
    !! 1e-6; 1e-4 for an asymmetric rig, whose periods are simulated; an input of value 0
    !! steps by that fraction of b'); an amplitude near 0 or 180 degrees is differenced on
    !! the side that stays inside.  On a rig where pure torsion is exact the inputs that do
    !! not enter pure torsion (I2, I3, the mass centre) have sensitivity 0 by symmetry
    !! (module inputs), and l, l' share the effect of their common length.  u_each: the
    !! standard uncertainty of each period (e.g. u_period / cycles), else u%period.
    !! fit_scale: the inversions fit the amplitudes' scale too (fit%scale_c: dk/dx of each
    !! row); u_amp_scale > 0: the row amplitude_scale (module header), and with fit_scale
    !! the inversions take it as the scale's prior.
    subroutine period_budget(rg, acc, periods, amps, u, fit, stat, x, u_each, fit_scale, &
                             u_amp_scale)
        type(rig_t), intent(in) :: rg           !! the rig
        type(accuracy_t), intent(in) :: acc     !! accuracy of simulated periods
        real(dp), intent(in) :: periods(:)      !! measured periods (s)
        real(dp), intent(in) :: amps(:)         !! their amplitudes (degrees)
        type(input_u_t), intent(in) :: u        !! standard uncertainties
        type(period_fit_t), intent(inout) :: fit    !! from invert_periods
        type(status_t), intent(out) :: stat
        type(input_t), intent(in), optional :: x(:)     !! the rig's inputs
        real(dp), intent(in), optional :: u_each(:)     !! each period's u (s)
        logical, intent(in), optional :: fit_scale      !! the scale fitted in each inversion
        real(dp), intent(in), optional :: u_amp_scale   !! the scale's relative u (not fitted)
        type(input_t), allocatable :: xs(:)
        type(budget_row_t), allocatable :: rows(:)
        type(start_t) :: st0
        real(dp), allocatable :: kc(:)
        real(dp) :: up(size(periods)), c, hx, hrel, ip, im, kp, km, h2, kl, us
        logical :: fs
        character(len=24) :: nm
        logical :: sym
        integer :: n, i, k
        n = size(periods)
        stat%code = 0
        sym = is_torsion_rig(rg)
        hrel = merge(FD_REL, FD_REL_SIM, sym)
        up = u%period
        if (present(u_each)) up = u_each
        fs = .false.
        if (present(fit_scale)) fs = fit_scale
        us = 0.0_dp
        if (present(u_amp_scale)) us = u_amp_scale
        kp = fit%scale
        km = fit%scale
        allocate (kc(0))
        if (present(x)) then
            xs = x
        else
            xs = [input_t('mass', rg%mass, u%mass), input_t('l', rg%l, u%l), &
                  input_t('l_prime', rg%l_prime, u%l_prime), input_t('b', rg%b, u%b), &
                  input_t('b_prime', rg%b_prime, u%b_prime), input_t('g', rg%g, u%g)]
        end if
        allocate (rows(0))
        do k = 1, size(xs)
            if (.not. (xs(k)%u > 0.0_dp)) cycle
            if (sym .and. no_effect_on_torsion(xs(k)%name)) then
                rows = [rows, budget_row_t(xs(k)%name, xs(k)%value, xs(k)%u, 0.0_dp, 0.0_dp, &
                                           ROW_INPUT)]
                kc = [kc, 0.0_dp]
                cycle
            end if
            hx = hrel*abs(xs(k)%value)
            if (.not. (hx > 0.0_dp)) hx = hrel*rg%b_prime
            if (trim(xs(k)%name) == 'lambda') hx = hrel
            call inverted_input(xs(k), xs(k)%value + hx, ip, stat)
            kp = kl
            if (stat%code == 0) call inverted_input(xs(k), xs(k)%value - hx, im, stat)
            km = kl
            if (stat%code /= 0) then
                stat%msg = 'uncertainty budget, input '//trim(xs(k)%name)//': '//stat%msg
                return
            end if
            c = (ip - im)/(2*hx)
            kc = [kc, (kp - km)/(2*hx)]
            rows = [rows, budget_row_t(xs(k)%name, xs(k)%value, xs(k)%u, c, abs(c)*xs(k)%u, &
                                       ROW_INPUT)]
        end do
        do i = 1, n
            if (.not. (up(i) > 0.0_dp)) cycle
            write (nm, '(a,i0,a)') 'period(', i, ')'
            hx = hrel*periods(i)
            call inverted_measured(i, periods(i) + hx, amps(i), ip, stat)
            kp = kl
            if (stat%code == 0) call inverted_measured(i, periods(i) - hx, amps(i), im, stat)
            km = kl
            if (stat%code /= 0) then
                stat%msg = 'uncertainty budget, input '//trim(nm)//': '//stat%msg
                return
            end if
            c = (ip - im)/(2*hx)
            kc = [kc, (kp - km)/(2*hx)]
            rows = [rows, budget_row_t(nm, periods(i), up(i), c, abs(c)*up(i), ROW_TIMING)]
        end do
        do i = 1, n
            if (.not. (u%amplitude > 0.0_dp)) cycle
            write (nm, '(a,i0,a)') 'amplitude(', i, ')'
            hx = hrel*max(1.0_dp, amps(i))
            if (amps(i) + hx < 180.0_dp .and. amps(i) - hx > 0.0_dp) then
                call inverted_measured(i, periods(i), amps(i) + hx, ip, stat)
                kp = kl
                if (stat%code == 0) call inverted_measured(i, periods(i), amps(i) - hx, im, stat)
                km = kl
                c = (ip - im)/(2*hx)
                kc = [kc, (kp - km)/(2*hx)]
            else
                ! one-sided, inside 0 .. 180 degrees
                hx = sign(hx, 90.0_dp - amps(i))
                call inverted_measured(i, periods(i), amps(i) + hx, ip, stat)
                c = (ip - fit%i1)/hx
                kc = [kc, (kl - fit%scale)/hx]
            end if
            if (stat%code /= 0) then
                stat%msg = 'uncertainty budget, input '//trim(nm)//': '//stat%msg
                return
            end if
            rows = [rows, budget_row_t(nm, amps(i), u%amplitude, c, abs(c)*u%amplitude, &
                                       ROW_AMPLITUDE)]
        end do
        if (us > 0.0_dp) then
            block
                ! every amplitude on one scale k (1 as read): dI1/dk of the whole inversion,
                ! one-sided when a step would pass 180 degrees
                ! (a larger step than the others': the periods often tell k better than
                ! its u, so I1 moves little with it)
                h2 = 1.0e-3_dp
                if (maxval(amps)*(1.0_dp + h2) < 180.0_dp) then
                    call inverted_scaled(1.0_dp + h2, ip, stat)
                    if (stat%code == 0) call inverted_scaled(1.0_dp - h2, im, stat)
                    c = (ip - im)/(2*h2)
                else
                    call inverted_scaled(1.0_dp - h2, im, stat)
                    c = (fit%i1 - im)/h2
                end if
                if (stat%code /= 0) then
                    stat%msg = 'uncertainty budget, input amplitude_scale: '//stat%msg
                    return
                end if
                rows = [rows, budget_row_t('amplitude_scale', 1.0_dp, us, c, abs(c)*us, &
                                           ROW_AMPLITUDE_SCALE)]
                kc = [kc, 0.0_dp]
            end block
        end if
        fit%budget = rows
        if (fs) fit%scale_c = kc
        fit%u_i1 = 0.0_dp
        if (size(rows) > 0) fit%u_i1 = sqrt(sum(rows%contribution**2))
    contains
        !> I1 with the rig's input xi set to v.
        subroutine inverted_input(xi, v, i1, st)
            type(input_t), intent(in) :: xi
            real(dp), intent(in) :: v
            real(dp), intent(out) :: i1
            type(status_t), intent(out) :: st
            type(rig_t) :: dd
            type(period_fit_t) :: f2
            dd = rg
            dd%inertia(1) = fit%i1
            if (sym .and. (trim(xi%name) == 'l' .or. trim(xi%name) == 'l_prime')) then
                ! mirror symmetry: each cable carries half the effect of the common length
                dd%l = rg%l + 0.5_dp*(v - xi%value)
                dd%l_prime = rg%l_prime + 0.5_dp*(v - xi%value)
            else
                call set_input(dd, st0, xi%name, v)
            end if
            call invert_periods(dd, acc, periods, amps, u, f2, st, u_each, fit_scale=fs, &
                                k_start=fit%scale, scale_prior=us)
            i1 = f2%i1
            kl = f2%scale
        end subroutine inverted_input
        !> I1 with period i and its amplitude set to (tp, ta).
        subroutine inverted_measured(i, tp, ta, i1, st)
            integer, intent(in) :: i
            real(dp), intent(in) :: tp, ta
            real(dp), intent(out) :: i1
            type(status_t), intent(out) :: st
            type(rig_t) :: dd
            type(period_fit_t) :: f2
            real(dp) :: pp(n), aa(n)
            dd = rg
            dd%inertia(1) = fit%i1
            pp = periods
            aa = amps
            pp(i) = tp
            aa(i) = ta
            call invert_periods(dd, acc, pp, aa, u, f2, st, u_each, fit_scale=fs, &
                                k_start=fit%scale, scale_prior=us)
            i1 = f2%i1
            kl = f2%scale
        end subroutine inverted_measured
        !> I1 with every amplitude times ks.
        subroutine inverted_scaled(ks, i1, st)
            real(dp), intent(in) :: ks
            real(dp), intent(out) :: i1
            type(status_t), intent(out) :: st
            type(rig_t) :: dd
            type(period_fit_t) :: f2
            dd = rg
            dd%inertia(1) = fit%i1
            call invert_periods(dd, acc, periods, amps*ks, u, f2, st, u_each, fit_scale=fs, &
                                k_start=fit%scale/ks, scale_prior=us)
            i1 = f2%i1
        end subroutine inverted_scaled
    end subroutine period_budget

    !> Monte Carlo sample k: every input drawn from N(value, u^2) with stream k of `seed`
    !! (draw order: mass, l, l_prime, b, b_prime, g, then period and amplitude of each
    !! measurement), then the inversion again; i1 is that sample's I1.
    subroutine period_mc_sample(rg, acc, periods, amps, u, i1_start, seed, k, i1, stat, x, &
                                cycles)
        type(rig_t), intent(in) :: rg           !! the rig
        type(accuracy_t), intent(in) :: acc     !! accuracy of simulated periods
        real(dp), intent(in) :: periods(:), amps(:)   !! measurements (s, degrees)
        type(input_u_t), intent(in) :: u        !! standard uncertainties
        real(dp), intent(in) :: i1_start        !! start of the inversion (e.g. the estimate)
        integer, intent(in) :: seed, k          !! seed and sample number
        real(dp), intent(out) :: i1             !! the sample's I1
        type(status_t), intent(out) :: stat
        !> the rig's inputs (module inputs): those beyond mass, l, l_prime, b, b_prime, g are
        !! drawn after the periods, in their order
        type(input_t), intent(in), optional :: x(:)
        real(dp), intent(in), optional :: cycles(:) !! each period spans that many cycles
        type(rng_t) :: g
        type(rig_t) :: dd
        type(start_t) :: st0
        type(period_fit_t) :: f
        real(dp) :: pp(size(periods)), aa(size(amps)), la, lb, up(size(periods))
        integer :: i
        g = rng_stream(seed, k)
        dd = rg
        dd%inertia(1) = i1_start
        dd%mass = rg%mass + u%mass*rng_normal(g)
        la = rg%l + u%l*rng_normal(g)
        lb = rg%l_prime + u%l_prime*rng_normal(g)
        if (is_torsion_rig(rg)) then
            dd%l = 0.5_dp*(la + lb)
            dd%l_prime = dd%l
        else
            dd%l = la
            dd%l_prime = lb
        end if
        dd%b = rg%b + u%b*rng_normal(g)
        call move_b_prime(dd, rg%b_prime + u%b_prime*rng_normal(g))
        dd%g = rg%g + u%g*rng_normal(g)
        up = u%period
        if (present(cycles)) up = u%period/cycles
        do i = 1, size(periods)
            pp(i) = periods(i) + up(i)*rng_normal(g)
            ! the peak amplitude's sign is no measurement: the period depends on |A|
            aa(i) = abs(amps(i) + u%amplitude*rng_normal(g))
        end do
        if (present(x)) then
            do i = 1, size(x)
                select case (trim(x(i)%name))
                case ('mass', 'l', 'l_prime', 'b', 'b_prime', 'g')
                case default
                    if (x(i)%u > 0.0_dp) call set_input(dd, st0, x(i)%name, &
                                                        x(i)%value + x(i)%u*rng_normal(g))
                end select
            end do
        end if
        call invert_periods(dd, acc, pp, aa, u, f, stat, up)
        i1 = f%i1
        if (stat%code /= 0) then
            ! the values are the sample's draws, not the deck's: what is allowed is a u
            if (stat%code == ERR_DECK) then
                i = index(stat%msg, '; allowed:')
                if (i > 0) stat%msg = stat%msg(1:i - 1)
                stat%msg = stat%msg//' (a draw of this sample from the deck''s values and '// &
                    'their u, not the deck''s own values); allowed: u_period, u_amplitude '// &
                    'and the rig''s u small enough that every draw is a period some positive '// &
                    'I1 gives'
            end if
            stat%msg = 'Monte Carlo sample '//itoa(k)//': '//stat%msg
        end if
    end subroutine period_mc_sample

    !> n Monte Carlo samples (period_mc_sample) as a sweep over the ranks and threads
    !! (module monte_carlo; the result does not depend on their number): the mean and the
    !! standard deviation of the sampled I1, or the failure of the first failed sample.
    !! With `outdir` the sweep is checkpointed there (OUTDIR/NAME.identify_mc.partial;
    !! options: --resume, the interval; report: how the sweep went; files: the run's staged
    !! files, removed on a signal).
    subroutine period_monte_carlo(d, rg, acc, x, periods, amps, u, i1_start, n, seed, mean, &
                                  sdev, stat, outdir, options, report, files, cycles)
        class(deck_source_t), intent(in) :: d   !! the deck's source (its path, name, text)
        type(rig_t), intent(in) :: rg           !! the deck's rig
        type(accuracy_t), intent(in) :: acc     !! its runs' accuracy
        type(input_t), intent(in) :: x(:)       !! its inputs (deck_inputs, .false.)
        real(dp), intent(in) :: periods(:), amps(:)   !! measurements (s, degrees)
        type(input_u_t), intent(in) :: u        !! standard uncertainties
        real(dp), intent(in) :: i1_start        !! start of each inversion
        integer, intent(in) :: n, seed          !! samples (>= 2) and seed
        real(dp), intent(out) :: mean, sdev     !! of the sampled I1
        type(status_t), intent(out) :: stat
        character(len=*), intent(in), optional :: outdir    !! checkpoints' folder
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(out), optional :: report
        type(out_files_t), intent(in), optional :: files
        !> the cycles each period spans (u%period is then the u of each timed total)
        real(dp), intent(in), optional :: cycles(:)
        type(period_mc_task_t) :: task
        real(dp), allocatable :: payload(:), cyc(:)
        real(dp) :: m(1), s(1)
        mean = 0.0_dp
        sdev = 0.0_dp
        stat%code = 0
        if (n < 2) then
            call set_error(stat, ERR_DECK, '&measurement monte_carlo = '//itoa(n)// &
                ': too few samples; allowed: at least 2')
            return
        end if
        allocate (cyc(size(periods)))
        cyc = 1.0_dp
        if (present(cycles)) cyc = cycles
        payload = period_mc_payload(periods, amps, u, i1_start, seed, cyc)
        call period_mc_task(rg, acc, x, payload, task)
        call monte_carlo_run(task, d, n, payload, m, s, stat, outdir, options, report, files)
        mean = m(1)
        sdev = s(1)
    end subroutine period_monte_carlo

    !> What a periods Monte Carlo needs beyond the rig, as reals (the sweep's payload):
    !! seed, i1_start, the eight standard uncertainties, the number of periods, the periods,
    !! their amplitudes, the cycles each spans.
    pure function period_mc_payload(periods, amps, u, i1_start, seed, cycles) result(p)
        real(dp), intent(in) :: periods(:), amps(:)   !! measurements (s, degrees)
        real(dp), intent(in) :: cycles(:)       !! cycles of each timed total
        type(input_u_t), intent(in) :: u        !! standard uncertainties
        real(dp), intent(in) :: i1_start        !! start of each inversion
        integer, intent(in) :: seed
        real(dp), allocatable :: p(:)
        p = [real(seed, dp), i1_start, u%mass, u%l, u%l_prime, u%b, u%b_prime, u%g, u%period, &
             u%amplitude, real(size(periods), dp), periods, amps, cycles]
    end function period_mc_payload

    !> The samples of a periods Monte Carlo of the deck's rig from their payload
    !! (period_mc_payload): the task rank 0 runs and the other ranks of an MPI run build.
    pure subroutine period_mc_task(rg, acc, x, payload, task)
        type(rig_t), intent(in) :: rg           !! the deck's rig
        type(accuracy_t), intent(in) :: acc     !! its runs' accuracy
        type(input_t), intent(in) :: x(:)       !! its inputs (deck_inputs, .false.)
        real(dp), intent(in) :: payload(:)      !! period_mc_payload
        type(period_mc_task_t), intent(out) :: task
        integer :: np
        task%rg = rg
        task%acc = acc
        task%seed = nint(payload(1))
        task%i1_start = payload(2)
        task%u = input_u_t(mass=payload(3), l=payload(4), l_prime=payload(5), b=payload(6), &
                           b_prime=payload(7), g=payload(8), period=payload(9), &
                           amplitude=payload(10))
        np = nint(payload(11))
        task%periods = payload(12:11 + np)
        task%amps = payload(12 + np:11 + 2*np)
        task%cycles = payload(12 + 2*np:11 + 3*np)
        task%x = x
        task%nest = 1
    end subroutine period_mc_task

    !> Sample k of a periods Monte Carlo (period_mc_sample): est(1) = the sample's I1.
    subroutine period_mc_point(self, k, est, stat)
        class(period_mc_task_t), intent(in) :: self
        integer, intent(in) :: k                !! sample number
        real(dp), intent(out) :: est(:)         !! I1
        type(status_t), intent(out) :: stat
        call period_mc_sample(self%rg, self%acc, self%periods, self%amps, self%u, self%i1_start, &
                              self%seed, k, est(1), stat, self%x, self%cycles)
    end subroutine period_mc_point

    !> The classical small-amplitude formula I1 = m g b b' T^2 / (16 pi^2 l) (deck units),
    !! with l the mean of the two cable lengths, (l + l')/2, as it is applied to a rig whose
    !! cables differ.
    pure real(dp) function linear_inertia(rg, t) result(i1)
        type(rig_t), intent(in) :: rg           !! the rig
        real(dp), intent(in) :: t               !! period (s)
        i1 = rg%mass*rg%g*rg%b*rg%b_prime*t**2/(16.0_dp*pi**2*(0.5_dp*(rg%l + rg%l_prime)))
    end function linear_inertia

end module period_inversion
