!> The fit of the paper's model to a record (the record analysis of identify): the
!! least-squares problem of the estimated parameters for the estimator (record_fit_t: I1
!! and any of c_v, c_q, the release amplitude, t0, a bias of the recorded quantity), the
!! release found in the record (find_release), the fit on growing windows (fit_record,
!! with Huber's loss when asked), the inputs' sensitivities (the first-order budget), the
!! residuals' correlation time, the Monte Carlo's samples (record_mc_task_t), and records
!! made by the program itself (make_record); the model at the record's sample times
!! (record_model, record_model_sens) and the evaluator that keeps its runs
!! (record_runs_t).  See module identify for the method.
!!
!! A platform: of three cables the platform's own model (module platform_measure, the
!! derivatives by central differences of whole runs); of more, the pure torsion of the
!! equivalent bifilar with the mass centre's depth taken positive.
!!
!! The model of a sample: sign (model(t; I1, damping, amplitude, t0)) + bias, where sign is
!! -1 for a body released the other way (found from the record's first swing) and the
!! model before t0 is the held start.  The instrument's three rates ('rates') are no mirror
!! image of the model when the turn reverses (the tilt and sway rates keep their way), nor
!! is a tracked point's position ('point', point_way): there sign is 1 and the model is
!! released the record's way instead (turn: the start amplitude, the deck's or the fitted
!! size, taken negative); a rates record that starts at its release has the release at its
!! first sample (rates_from_rest).  A record that starts mid-swing is fitted from its
!! first turning point on (ifirst): a turning point is a moment at rest, from which the
!! model is a release.
!!
!! Derivatives of the model (&integration sensitivities = 'forward', the default): one run
!! carries the forward sensitivities of every quantity asked (record_model_sens: the fit's
!! parameters for its Jacobian, the budget's inputs for their sensitivities).  A quantity
!! moves the scaled pendulum (its direction, sens_dir_t, from central differences of
!! make_pendulum, which is algebraic), the start (central differences of start_state: the
!! initial condition of its sensitivity), the time scale sqrt(g/b') and the release time t0;
!! the last two move the samples along the motion, f(y) from the integrator's dense output.
!! With 'differences' the Jacobian and the inputs' sensitivities are differences of whole
!! runs, as before.
!!
!! The runs a fit makes go through its evaluator (record_runs_t, an object of the problem):
!! the model is a function of the rig, the start and the release only (a run_point_t; the
!! weights, the bias and the sign of a fit act on its values), so the last run is kept,
!! keyed by that point compared by value, and an evaluation of the same point whose
!! samples it reached takes it instead of a run.  The estimator tells the evaluator the
!! Gauss-Newton gain of each point it evaluates with derivatives (note_gain); from that:
!! * a whole-record run after one within a standard error of the minimum (gain <=
!!   CARRY_GAIN) carries the budget's inputs beside the fit's parameters (the fit ends
!!   there as a rule, and the budget then needs no run of its own: carried);
!! * a whole-record run that does not carry them takes the derivatives of the last
!!   whole-record point where they were computed again when that point's gain was within
!!   REUSE_GAIN (the step from it within 100 standard errors: over so short a step the
!!   derivatives change in their fourth digit or later) and runs the model alone
!!   (runs%jac_fresh .false.); the Jacobian at the estimate is always computed there
!!   (fresh_jacobian);
!! * neither with the sensitivities in the error control (there a column changes the steps
!!   of the others, and a run without them other steps).
module record_fit
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC
    use text, only: itoa, sci, rshort
    use measure_groups, only: measurement_group_t, parse_axes
    use output_io, only: out_files_t, all_finite
    use geometry, only: pendulum_t, body_pose, frame, body_axes
    use bifilar_model, only: NSTATE, bifilar_t, sens_dir_t, vertical_rate, &
        vertical_rate_gradient
    use rig, only: rig_t, start_t, accuracy_t, make_pendulum, start_state
    use kane_run, only: kane_run_start, kane_run_t
    use run_loop, only: stepped_model_t, row_sink_t, drive
    use integrators, only: SENS_FORWARD
    use estimator, only: lsq_problem_t, lsq_options_t, lsq_result_t, estimate, &
        gauss_newton_gain, lsq_covariance, LOSS_SQUARES, lsq_jacobian
    use rig, only: same_rig, same_start
    use lapack_wrap, only: la_lstsq, la_svd
    use random, only: rng_t, rng_stream, rng_normal
    use records, only: record_t, mean_period, median_value
    use inputs, only: input_t, set_input, input_value
    use monte_carlo, only: mc_task_t
    use platform_measure, only: platform_records, torsion_equivalent, platform_record
    implicit none
    private

    !> Parameters a record fit can estimate (deck ESTIMATES_ALLOWED), in this order: the
    !! first six of any record; I2, I3, cg_depth (the body's other moments and the depth of
    !! its mass centre below CD), tilt and sway (the release's start values, &start tilt and
    !! sway) of any record, which a record determines only when its release tilts or sways;
    !! bias_y and bias_z, with bias (then the x axis's), the three offsets of quantity
    !! 'rates' (estimate = 'bias' asks for all three).
    integer, parameter, public :: P_I1 = 1, P_CV = 2, P_CQ = 3, P_AMP = 4, P_T0 = 5, P_BIAS = 6
    integer, parameter, public :: P_I2 = 7, P_I3 = 8, P_CG = 9, P_TILT = 10, P_SWAY = 11, &
        P_BIAS_Y = 12, P_BIAS_Z = 13
    !> scale, scale_y, scale_z: the record's scale (record_scale, the quantity per unit of
    !! a column: the model of a column is its value over the scale), one for quantity
    !! 'point' (both columns), each axis's with quantity 'rates' (estimate = 'scale' asks
    !! for all three), the one column's otherwise.
    integer, parameter, public :: P_SCALE = 14, P_SCALE_Y = 15, P_SCALE_Z = 16
    integer, parameter, public :: NPARAM = 16
    character(len=9), parameter, public :: PARAM_NAMES(NPARAM) = [character(len=9) :: 'I1', &
        'c_v', 'c_q', 'amplitude', 't0', 'bias', 'I2', 'I3', 'cg_depth', 'tilt', 'sway', &
        'bias_y', 'bias_z', 'scale', 'scale_y', 'scale_z']
    !> Quantity 'point': the camera's view, VIEW_BELOW (looking up the vertical: the point's
    !! horizontal position, n_1 and n_2 components) or VIEW_SIDE (looking along n_1: the
    !! horizontal n_2 component and the vertical n_3 one, up).
    integer, parameter, public :: VIEW_BELOW = 1, VIEW_SIDE = 2

    !> What a run of the record model depends on: the rig, the start and the release.
    type, public :: run_point_t
        type(rig_t) :: rg                       !! the rig (I1, damping as fitted)
        type(start_t) :: st                     !! the start (amplitude as fitted)
        real(dp) :: t0 = 0.0_dp                 !! the release (s)
    end type run_point_t

    !> The quantities whose derivatives a run carries: a fit parameter ('I1', 'c_v', 'c_q',
    !! 'amplitude', 't0') or an input of module inputs, and the size of each (deck units;
    !! its difference steps are 1e-5 of it).
    type, public :: run_columns_t
        character(len=16), allocatable :: names(:)
        real(dp), allocatable :: xs(:)
    end type run_columns_t

    !> The evaluator of the record model: its runs, the last one kept, and the carry and
    !! reuse of derivatives (see the module header).
    type, public :: record_runs_t
        type(accuracy_t) :: acc                 !! the runs' accuracy (rtol, atol, integrator)
        logical :: rate = .false.               !! W instead of theta4
        !> quantity 'rates': the three rates an instrument fixed on the body reads (rad/s),
        !! axes(k, :) its axis k in the body's principal axes b_1, b_2, b_3 (a run's values
        !! are then three blocks of the samples, one per axis)
        logical :: rates = .false.
        real(dp) :: axes(3, 3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                          0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
        !> quantity 'point': the position (m) of the body's point q (m, in the principal
        !! axes from the mass centre) the camera sees (view: VIEW_BELOW, VIEW_SIDE) less its
        !! position at zero angles (point_position); a run's values two blocks of the samples
        logical :: point = .false.
        real(dp) :: q(3) = 0.0_dp
        integer :: view = VIEW_BELOW
        !> The budget's inputs (set_carry) and the columns of those with u > 0, which a
        !! whole-record run near the minimum carries
        type(input_t), allocatable :: x(:)
        type(run_columns_t) :: carry
        ! the last run
        logical :: valid = .false.
        type(run_point_t) :: key                !! its point
        integer :: n = 0                        !! the samples it reached
        integer :: nfit = 0                     !! its columns of the fit's parameters
        integer :: nx = 0                       !! its columns of the budget's inputs
        real(dp), allocatable :: v(:)           !! the model at those samples
        real(dp), allocatable :: dv(:, :)       !! its derivatives: the fit's, the inputs'
        !> The gain the estimator noted at the last whole-record point
        real(dp) :: whole_gain = huge(1.0_dp)
        !> The derivatives (the fit's columns) of the last whole-record point where they were
        !! computed, and the gain there: what a next point within REUSE_GAIN takes again
        real(dp), allocatable :: jac_dv(:, :)
        real(dp) :: jac_gain = huge(1.0_dp)
        !> The last evaluation's derivatives were computed at its point (not taken again)
        logical :: jac_fresh = .true.
        !> The last evaluation with derivatives was of the whole record; fresh_dv: its
        !! derivatives when computed there (kept as jac_dv once its gain is noted)
        logical :: last_whole = .false.
        real(dp), allocatable :: fresh_dv(:, :)
    contains
        procedure :: run
        procedure :: values
        procedure :: note_gain
        procedure :: carried
        procedure :: forget
        procedure :: set_carry
    end type record_runs_t

    !> The record fit as a least-squares problem: residuals
    !! (sign model + bias - measured)/u_i, times the robust weights' roots, over the samples
    !! ifirst .. nuse.
    type, extends(lsq_problem_t), public :: record_fit_t
        type(rig_t) :: rg                       !! the rig, every held value (inputs)
        type(start_t) :: st                     !! the start (its amplitude may be fitted)
        type(accuracy_t) :: acc                 !! the model runs' accuracy
        integer :: seed = 1                     !! the Monte Carlo's seed
        type(record_t) :: rec                   !! the record (values perturbed by Monte Carlo)
        integer :: np = 0                       !! parameters estimated
        integer :: which(NPARAM) = 0            !! P_* of each estimated parameter
        real(dp) :: t0 = 0.0_dp                 !! release time (s), when held
        real(dp) :: bias(3) = 0.0_dp            !! the record's offset (each axis), when held
        real(dp) :: sign = 1.0_dp               !! -1: the body was released the other way
        !> quantity 'rates' or 'point': the release's way (-1: turned the other way); the
        !! model's start amplitude is turn times the amplitude's size (the deck's or the
        !! fitted one), the outputs keep their sign (tilt and sway do not mirror)
        real(dp) :: turn = 1.0_dp
        logical :: rate = .false.               !! quantity = 'rate' (or 'rates')
        !> quantity 'rates': three values a sample (rec%vs), axes(k, :) the instrument's axis
        !! k in the body's principal axes; the residuals are three blocks of the samples
        logical :: rates = .false.
        !> quantity 'point': two values a sample (rec%vs), the position of the body's point q
        !! (m) seen from view (record_runs_t); scale(k): the record's scale of value k
        logical :: point = .false.
        real(dp) :: q(3) = 0.0_dp
        integer :: view = VIEW_BELOW
        real(dp) :: scale(3) = 1.0_dp
        integer :: vcol = 1                     !! 'point': the coordinate rec%v holds
        integer :: nout = 1                     !! values a sample: 1, 2 ('point') or 3 ('rates')
        real(dp) :: axes(3, 3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                          0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
        integer :: ifirst = 1                   !! first sample fitted
        integer :: nuse = 0                     !! last sample fitted (the window)
        real(dp), allocatable :: w(:)           !! 1/u_i (1 without u)
        real(dp), allocatable :: hw(:)          !! the roots of the robust weights (1: squares)
        real(dp) :: xs(NPARAM) = 1.0_dp         !! the size of each estimated parameter
        !> The evaluator of the model (record_runs_t): the last run kept, the budget's
        !! inputs (carry_inputs) that a run of the whole record near the minimum carries
        !! beside the fit's derivatives, so that the budget at the estimate
        !! (input_sensitivities) takes them from the fit's last run; the Jacobian taken
        !! again (runs%jac_fresh .false. after an evaluation that did)
        type(record_runs_t) :: runs
    contains
        procedure :: residual => record_residual
        procedure :: nres => record_nres
        procedure :: has_jacobian => record_has_jacobian
        procedure :: residual_jacobian => record_residual_jacobian
        procedure :: note_gain => record_note_gain
    end type record_fit_t

    !> Where the swing starts in a record, as find_release sees it: the start values of a
    !! fit of the release (module measurement's release_t is the release itself).
    type, public :: record_start_t
        logical :: held = .false.               !! the record starts with the body held still
        real(dp) :: t0 = 0.0_dp                 !! the release (or first turning point), s
        integer :: ifirst = 1                   !! first sample to fit
        real(dp) :: amplitude = 0.0_dp          !! degrees, estimated from the record
        real(dp) :: sign = 1.0_dp               !! the first swing's direction
        real(dp) :: level = 0.0_dp              !! the held level or the swing's centre
        real(dp) :: period = 0.0_dp             !! the mean period after the release (s)
    end type record_start_t

    !> The model's value at the record's sample times (a sink of the run loop).
    type, extends(row_sink_t) :: record_sink_t
        logical :: rate = .false.
        logical :: rates = .false.              !! the instrument's three rates
        integer :: nout = 1                     !! values a sample
        real(dp) :: axes(3, 3) = 0.0_dp         !! the instrument's axes (rates)
        real(dp) :: btilde(3, 3) = 0.0_dp       !! the body's principal axes (rates)
        !> quantity 'point': the body's point (m), the view, the pendulum and b' (m) of the
        !! run, and of each column moved by +-hc(c) (the position's own change along the
        !! column at a fixed state: point_partial)
        logical :: point = .false.
        real(dp) :: q(3) = 0.0_dp
        integer :: view = VIEW_BELOW
        type(pendulum_t) :: p
        real(dp) :: bp = 1.0_dp
        type(pendulum_t), allocatable :: pp(:), pm(:)
        real(dp), allocatable :: bpp(:), bpm(:), hc(:)
        real(dp), allocatable :: vals(:, :)     !! (nout, 0:) theta4 (rad) or W, or the rates
                                                !! (rad per unit tau)
        integer :: ns = 0                       !! forward sensitivities carried (0: none)
        real(dp), allocatable :: dvals(:, :, :) !! (ns, nout, 0:) the values' change along each
        logical :: shift = .false.              !! the value's rate is asked too
        real(dp), allocatable :: slope(:, :)    !! (nout, 0:) its rate, d value/d tau
    contains
        procedure :: take => record_take
    end type record_sink_t

    !> What a record determines of the parameters it estimates (record_determines).
    type, public :: determines_t
        integer :: np = 0                       !! parameters
        real(dp) :: cond = 1.0_dp               !! condition number of J, columns scaled
        real(dp) :: corr_max = 0.0_dp           !! largest |off-diagonal| of the correlations
        integer :: pair(2) = 0                  !! its two parameters
        integer :: flat = 0                     !! a parameter the record does not depend on
    end type determines_t

    !> The samples of a record fit's Monte Carlo (record_mc_point) as a sweep: the fit
    !! problem, the estimate the samples start from, its Jacobian and first-order u, s, and
    !! the inputs drawn; built by record_mc_task from the deck, the record and the payload.
    type, extends(mc_task_t), public :: record_mc_task_t
        type(record_fit_t) :: prob              !! the fit (deck, record, weights)
        real(dp), allocatable :: phat(:)        !! the estimate
        real(dp), allocatable :: jac(:, :)      !! the Jacobian there (residuals, parameters)
        real(dp), allocatable :: u_p(:)         !! first-order u of each parameter
        real(dp) :: sigma = 0.0_dp              !! s of the covariance
        type(input_t), allocatable :: x(:)      !! the inputs drawn: names, values, u
        !> (np, size(x)) the parameters' first-order change per unit of each input (0 for an
        !! input without u); with it (forward sensitivities) a refit starts from the
        !! sample's first-order estimate
        real(dp), allocatable :: dpdx(:, :)
    contains
        procedure :: sample => record_mc_point
    end type record_mc_task_t

    public :: record_model, record_model_sens, fit_problem, fit_record, carry_inputs
    public :: input_sensitivity, input_sensitivities
    public :: record_mc_task, explain_fit_failure, make_record, find_release, check_record_kind
    public :: correlation_time, apply_parameters, fresh_jacobian, estimated_names
    public :: body_rates, body_rates_gradient, record_determines
    public :: stacked_values, stacked_weights, vertical_of_rates
    public :: point_position, point_gradient, runs_nout

    real(dp), parameter, public :: H_REL = 1.0e-5_dp        !! relative difference step of the model
    real(dp), parameter :: DAMP_REF = 1.0e-3_dp     !! scale of c_v, c_q (model's units)
    !> The size of a start's tilt or sway (rad) for their difference steps and columns
    real(dp), parameter :: SMALL_ANGLE = 1.0e-2_dp
    !> A parameter whose column's effect is below this part of the largest is one the
    !! record does not depend on; two whose correlation exceeds CORR_REFUSE, or a
    !! condition number (columns scaled to unit norm) beyond COND_REFUSE, it cannot separate
    real(dp), parameter :: FLAT_REL = 1.0e-6_dp, CORR_REFUSE = 0.9999_dp, COND_REFUSE = 1.0e8_dp
    !> The contraction rate a Monte Carlo refit's first step is taken to have (the rates
    !! measured on the example records are 0.005 ... 0.1)
    real(dp), parameter :: MC_RATE = 0.25_dp
    !> A Monte Carlo refit ends when its error is below this part of each parameter's u: an
    !! error e of each sample adds e^2 to the samples' variance, 1e-4 of u^2, where 200
    !! samples know their variance to 10 %
    real(dp), parameter :: MC_TOL = 1.0e-2_dp
    !> A whole-record run after one whose Gauss-Newton gain is at most this carries the
    !! budget's inputs (values)
    real(dp), parameter :: CARRY_GAIN = 1.0_dp
    !> A whole-record evaluation that does not carry the budget takes the derivatives of the
    !! last whole-record point again when that point's Gauss-Newton gain was at most this
    real(dp), parameter :: REUSE_GAIN = 1.0e4_dp

contains

    !> The model at the record's first n sample times, for the rig rg started by st with
    !! release at t0 (s): theta4 (rad) or W = omega . n3 (rad/s) when rate; with axes, the
    !! three rates (rad/s) of an instrument fixed on the body whose axis k is axes(k, :) in
    !! the body's principal axes, vals three blocks of n (body_rates).  A sample before
    !! t0 sees the start.  The model runs through the run loop (accuracy acc: rtol, atol,
    !! integrator), in memory.
    subroutine record_model(rg, st, acc, t, t0, rate, vals, stat, axes, point, view)
        type(rig_t), intent(in) :: rg           !! the rig (I1, damping as fitted)
        type(start_t), intent(in) :: st         !! the start (amplitude as fitted)
        type(accuracy_t), intent(in) :: acc     !! rtol, atol, integrator
        real(dp), intent(in) :: t(:)            !! sample times (s), increasing
        real(dp), intent(in) :: t0              !! release (s)
        logical, intent(in) :: rate             !! W instead of theta4
        real(dp), intent(out) :: vals(:)        !! the model at t(1:size(vals)) (or 3 blocks)
        type(status_t), intent(out) :: stat     !! the start's or the run's failure
        real(dp), intent(in), optional :: axes(3, 3)    !! quantity 'rates': the instrument's
        !> quantity 'point': the body's point (m, principal axes from the mass centre), and
        !! the view (VIEW_BELOW, the default, or VIEW_SIDE): vals two blocks of n
        real(dp), intent(in), optional :: point(3)
        integer, intent(in), optional :: view
        type(record_runs_t) :: ev
        type(run_columns_t) :: none
        real(dp) :: dv(size(vals), 0)
        ev%acc = acc
        ev%rate = rate
        if (present(axes)) then
            ev%rates = .true.
            ev%rate = .true.
            ev%axes = axes
        end if
        if (present(point)) then
            ev%point = .true.
            ev%q = point
            if (present(view)) ev%view = view
        end if
        allocate (none%names(0), none%xs(0))
        call ev%run(run_point_t(rg, st, t0), t, none, vals, dv, stat)
    end subroutine record_model

    !> record_model and its derivatives dvals(:, c) with respect to the quantities names(c)
    !! (a fit parameter, 'I1', 'c_v', 'c_q', 'amplitude', 't0', or an input of module
    !! inputs), from the forward sensitivities of one run (see the module header); xs(c) the
    !! size of quantity c (its difference steps are 1e-5 xs(c)).
    subroutine record_model_sens(rg, st, acc, t, t0, rate, names, xs, vals, dvals, stat, axes, &
                                 point, view)
        type(rig_t), intent(in) :: rg           !! the rig
        type(start_t), intent(in) :: st         !! the start
        type(accuracy_t), intent(in) :: acc     !! rtol, atol, integrator
        real(dp), intent(in) :: t(:)            !! sample times (s), increasing
        real(dp), intent(in) :: t0              !! release (s)
        logical, intent(in) :: rate             !! W instead of theta4
        character(len=*), intent(in) :: names(:)    !! the quantities
        real(dp), intent(in) :: xs(:)           !! their sizes (deck units)
        real(dp), intent(out) :: vals(:)        !! the model at t(1:size(vals))
        real(dp), intent(out) :: dvals(:, :)    !! (size(vals), size(names))
        type(status_t), intent(out) :: stat     !! the start's or the run's failure
        real(dp), intent(in), optional :: axes(3, 3)    !! quantity 'rates': the instrument's
        !> quantity 'point': the body's point (m, principal axes from the mass centre), and
        !! the view (VIEW_BELOW, the default, or VIEW_SIDE): vals two blocks of n
        real(dp), intent(in), optional :: point(3)
        integer, intent(in), optional :: view
        type(record_runs_t) :: ev
        type(run_columns_t) :: cols
        ev%acc = acc
        ev%rate = rate
        if (present(axes)) then
            ev%rates = .true.
            ev%rate = .true.
            ev%axes = axes
        end if
        if (present(point)) then
            ev%point = .true.
            ev%q = point
            if (present(view)) ev%view = view
        end if
        allocate (cols%names(size(names)))
        cols%names = names
        cols%xs = xs
        call ev%run(run_point_t(rg, st, t0), t, cols, vals, dvals, stat)
    end subroutine record_model_sens

    !> One run of the model over the samples t(1:n) at the point pt (rig, start, release),
    !! with the derivatives of the quantities cols (none: the values alone); n = size(vals)
    !! (quantity 'rates': size(vals)/3, vals three blocks of n, one per instrument axis).
    !! Column c of the run's sensitivities follows cols%names(c): its pendulum direction and
    !! initial condition by central differences of make_pendulum and start_state.  A
    !! quantity that moves the time scale s = sqrt(g/b') or the release moves the samples
    !! along the motion: a sample at t is the model at tau = (t - t0) s, so dv/dx = (dv/dy)
    !! (s_x + f (t - t0) ds/dx - f s dt0/dx) (times s, plus v ds/dx, for W), f = dy/dtau
    !! from the integrator's dense output (the system is autonomous: f(y(tau)) is the
    !! sensitivity to a shift of time, which needs no column of its own).
    subroutine run(self, pt, t, cols, vals, dvals, stat)
        class(record_runs_t), intent(in) :: self
        type(run_point_t), intent(in) :: pt     !! rig, start, release
        real(dp), intent(in) :: t(:)            !! sample times (s), increasing
        type(run_columns_t), intent(in) :: cols !! the quantities differentiated
        real(dp), intent(out) :: vals(:)        !! the model at t(1:n) (nout blocks)
        real(dp), intent(out) :: dvals(:, :)    !! (size(vals), size(cols%names))
        type(status_t), intent(out) :: stat     !! the start's or the run's failure
        real(dp), parameter :: FD_REL = 1.0e-5_dp
        type(pendulum_t) :: p, pp, pm
        type(kane_run_t) :: m
        type(record_sink_t) :: sink
        type(rig_t) :: rp, rm
        type(start_t) :: sp, sm
        type(sens_dir_t), allocatable :: dirs(:)
        real(dp) :: y0(NSTATE), th0(5), s, yp(NSTATE), ym(NSTATE), th(5), h
        real(dp) :: sfac, dtau
        real(dp), allocatable :: taus(:), s0(:, :), scale(:), ds(:), dt0(:), v0(:), g0(:, :)
        real(dp), allocatable :: pg0(:, :)
        type(rig_t) :: rg
        type(start_t) :: st
        type(accuracy_t) :: acc
        character(len=16) :: names(size(cols%names))
        real(dp) :: xs(size(cols%names))
        real(dp) :: t0
        integer :: n, i0, i, nq, ns, c, nout, k, o
        logical :: shift, rate
        rg = pt%rg
        st = pt%st
        t0 = pt%t0
        acc = self%acc
        rate = (self%rate .or. self%rates) .and. .not. self%point
        names = cols%names
        xs = cols%xs
        nout = runs_nout(self)
        n = size(vals)/nout
        nq = size(names)
        vals = 0.0_dp
        dvals = 0.0_dp
        if (platform_records(rg)) then
            ! a platform of three cables: the platform's own model, the derivatives by
            ! central differences of whole runs
            call platform_record(rg, st, acc, t, t0, rate, vals, stat)
            if (stat%code /= 0) return
            allocate (s0(n, 2))
            do c = 1, nq
                h = FD_REL*xs(c)
                if (trim(names(c)) == 't0') then
                    call platform_record(rg, st, acc, t, t0 + h, rate, s0(:, 1), stat)
                    if (stat%code == 0) call platform_record(rg, st, acc, t, t0 - h, rate, &
                                                             s0(:, 2), stat)
                else
                    call moved(names(c), h, rp, sp)
                    call moved(names(c), -h, rm, sm)
                    call platform_record(rp, sp, acc, t, t0, rate, s0(:, 1), stat)
                    if (stat%code == 0) call platform_record(rm, sm, acc, t, t0, rate, &
                                                             s0(:, 2), stat)
                end if
                if (stat%code /= 0) return
                dvals(:, c) = (s0(:, 1) - s0(:, 2))/(2.0_dp*h)
            end do
            return
        end if
        rg = torsion_equivalent(rg)
        call make_pendulum(rg, p, stat)
        if (stat%code /= 0) return
        call start_state(st, p, y0, th0, stat)
        if (stat%code /= 0) return
        s = sqrt(rg%g/rg%b_prime)               ! tau per second
        sfac = merge(s, 1.0_dp, rate)
        ! the quantities' directions, initial conditions, changes of s and of t0
        allocate (dirs(nq), ds(nq), dt0(nq), s0(NSTATE, nq), scale(nq))
        s0 = 0.0_dp
        scale = 1.0_dp
        ds = 0.0_dp
        dt0 = 0.0_dp
        do c = 1, nq
            scale(c) = 1.0_dp/max(xs(c), tiny(1.0_dp))
            if (trim(names(c)) == 't0') then
                dt0(c) = 1.0_dp
                cycle
            end if
            h = FD_REL*xs(c)
            call moved(names(c), h, rp, sp)
            call moved(names(c), -h, rm, sm)
            call make_pendulum(rp, pp, stat)
            if (stat%code == 0) call make_pendulum(rm, pm, stat)
            if (stat%code /= 0) return
            dirs(c)%inertia = (pp%inertia - pm%inertia)/(2.0_dp*h)
            dirs(c)%c_v = (pp%c_v - pm%c_v)/(2.0_dp*h)
            dirs(c)%c_q = (pp%c_q - pm%c_q)/(2.0_dp*h)
            dirs(c)%big_l = (pp%big_l - pm%big_l)/(2.0_dp*h)
            dirs(c)%big_lp = (pp%big_lp - pm%big_lp)/(2.0_dp*h)
            dirs(c)%big_b = (pp%big_b - pm%big_b)/(2.0_dp*h)
            dirs(c)%r = (pp%r - pm%r)/(2.0_dp*h)
            dirs(c)%lambda = (pp%lambda - pm%lambda)/(2.0_dp*h)
            ds(c) = (sqrt(rp%g/rp%b_prime) - sqrt(rm%g/rm%b_prime))/(2.0_dp*h)
            if (any([dirs(c)%big_l, dirs(c)%big_lp, dirs(c)%big_b, dirs(c)%r, &
                     dirs(c)%lambda] /= 0.0_dp) .or. trim(names(c)) == 'amplitude' .or. &
                trim(names(c)) == 'tilt' .or. trim(names(c)) == 'sway') then
                call start_state(sp, pp, yp, th, stat)
                if (stat%code == 0) call start_state(sm, pm, ym, th, stat)
                if (stat%code /= 0) return
                s0(:, c) = (yp - ym)/(2.0_dp*h)
            end if
        end do
        shift = any(ds /= 0.0_dp) .or. any(dt0 /= 0.0_dp)
        ns = nq
        if (self%point) then
            ! the point's position depends on the rig at a fixed state too (b', L, B, r,
            ! lambda): the pendulums of each column moved, for point_partial
            sink%point = .true.
            sink%q = self%q
            sink%view = self%view
            sink%p = p
            sink%bp = rg%b_prime
            allocate (sink%pp(nq), sink%pm(nq), sink%bpp(nq), sink%bpm(nq), sink%hc(nq))
            do c = 1, nq
                sink%pp(c) = p
                sink%pm(c) = p
                sink%bpp(c) = rg%b_prime
                sink%bpm(c) = rg%b_prime
                sink%hc(c) = 1.0_dp
                if (trim(names(c)) == 't0') cycle
                h = FD_REL*xs(c)
                call moved(names(c), h, rp, sp)
                call moved(names(c), -h, rm, sm)
                call make_pendulum(rp, sink%pp(c), stat)
                if (stat%code == 0) call make_pendulum(rm, sink%pm(c), stat)
                if (stat%code /= 0) return
                sink%bpp(c) = rp%b_prime
                sink%bpm(c) = rm%b_prime
                sink%hc(c) = h
            end do
        end if
        sink%rate = rate
        sink%rates = self%rates
        sink%nout = nout
        sink%axes = self%axes
        sink%btilde = p%btilde
        sink%ns = ns
        sink%shift = shift
        allocate (v0(nout), g0(NSTATE, nout))
        call sink_outputs(sink, y0, v0, g0)
        i0 = n + 1
        do i = 1, n
            if (t(i) >= t0) then
                i0 = i
                exit
            end if
        end do
        ! the samples before the release (or all, when the record ends at it) see the start
        if (n > 0) then
            if (i0 > n .or. (t(n) - t0)*s <= 0.0_dp) i0 = n + 1
        end if
        do o = 1, nout
            k = (o - 1)*n
            vals(k + 1:k + i0 - 1) = v0(o)*sfac
            do c = 1, nq
                dvals(k + 1:k + i0 - 1, c) = dot_product(g0(:, o), s0(:, c))*sfac
                if (rate) dvals(k + 1:k + i0 - 1, c) = dvals(k + 1:k + i0 - 1, c) + v0(o)*ds(c)
            end do
        end do
        if (self%point .and. i0 > 1) then
            pg0 = point_partial(sink, y0)
            do o = 1, nout
                k = (o - 1)*n
                do c = 1, nq
                    dvals(k + 1:k + i0 - 1, c) = dvals(k + 1:k + i0 - 1, c) + pg0(o, c)
                end do
            end do
        end if
        if (i0 > n) return
        allocate (taus(0:n - i0), sink%vals(nout, 0:n - i0), sink%dvals(ns, nout, 0:n - i0), &
                  sink%slope(nout, 0:n - i0))
        taus = (t(i0:n) - t0)*s
        if (ns > 0) then
            call kane_run_start(m, p, y0, th0(3), acc%rtol, acc%atol, acc%method, &
                                taus(n - i0), 'raise &integration rtol/atol', stat, &
                                s0=s0(:, 1:ns), dirs=dirs, scale=scale(1:ns), &
                                sens_error_control=acc%sens_error_control)
        else
            call kane_run_start(m, p, y0, th0(3), acc%rtol, acc%atol, acc%method, &
                                taus(n - i0), 'raise &integration rtol/atol', stat)
        end if
        if (stat%code /= 0) return
        call drive(m, taus, sink, stat)
        if (stat%code /= 0) return
        do o = 1, nout
            k = (o - 1)*n
            vals(k + i0:k + n) = sink%vals(o, :)*sfac
            do c = 1, nq
                do i = i0, n
                    dtau = (t(i) - t0)*ds(c) - s*dt0(c)
                    if (shift) then
                        dvals(k + i, c) = (sink%dvals(c, o, i - i0) + &
                                           sink%slope(o, i - i0)*dtau)*sfac
                    else
                        dvals(k + i, c) = sink%dvals(c, o, i - i0)*sfac
                    end if
                    if (rate) dvals(k + i, c) = dvals(k + i, c) + sink%vals(o, i - i0)*ds(c)
                end do
            end do
        end do
    contains
        !> The rig and start with quantity `name` moved by dx.
        subroutine moved(name, dx, r2, s2)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: dx
            type(rig_t), intent(out) :: r2
            type(start_t), intent(out) :: s2
            r2 = rg
            s2 = st
            select case (trim(name))
            case ('I1')
                r2%inertia(1) = rg%inertia(1) + dx
            case ('c_v')
                r2%c_v = rg%c_v + dx
            case ('c_q')
                r2%c_q = rg%c_q + dx
            case ('tilt')
                s2%tilt = st%tilt + dx
            case ('sway')
                s2%sway = st%sway + dx
            case default
                call set_input(r2, s2, name, input_value(rg, st, name) + dx)
            end select
        end subroutine moved
    end subroutine run

    !> The values a sample of the evaluator's runs has: 1, 2 (quantity 'point') or 3
    !! ('rates').
    pure integer function runs_nout(self) result(nout)
        class(record_runs_t), intent(in) :: self
        nout = 1
        if (self%rates) nout = 3
        if (self%point) nout = 2
    end function runs_nout

    !> The position (m) of the body's point q at a chart state, as the camera sees it: the
    !! point P = R* + q_i b_i (q in the principal axes b_i from the mass centre R*, eqs.
    !! (11), (21)-(22)), R* = C + r (s_lam ntilde_1 - c_lam ntilde_3), C = B + L e (the
    !! cable's direction e from the state's sigma), A the origin; view VIEW_BELOW: its n_1
    !! and n_2 components; VIEW_SIDE: its n_2 and n_3 ones.  p the scaled pendulum, bp = b'
    !! (m): P = b' (C + a_k ntilde_k), a = r (s_lam, 0, -c_lam) + btilde^T q / b'.
    pure function point_position(p, bp, q, view, y) result(x)
        type(pendulum_t), intent(in) :: p       !! the scaled pendulum
        real(dp), intent(in) :: bp              !! b' (m)
        real(dp), intent(in) :: q(3)            !! the point in the principal axes (m)
        integer, intent(in) :: view             !! VIEW_BELOW or VIEW_SIDE
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp) :: x(2)
        real(dp) :: n(3, 3), a(3), e(3), pos(3)
        call frame(body_pose(y(1), y(4), y(5), 0.0_dp), n)
        e = [y(2), y(3), -sqrt(max(0.0_dp, 1.0_dp - y(2)**2 - y(3)**2))]
        a = p%r*[sin(p%lambda), 0.0_dp, -cos(p%lambda)] + matmul(transpose(p%btilde), q)/bp
        pos = bp*([p%big_l*e(1), -p%big_b + p%big_l*e(2), p%big_l*e(3)] + matmul(a, n))
        x = seen(pos, view)
    end function point_position

    !> The gradient of point_position with respect to the chart state, g(:, k) for value
    !! k: the cable's sigma moves C by L (1, 0, sigma_1/zeta) and L (0, 1, sigma_2/zeta); an
    !! angle moves a_k ntilde_k by a_k dntilde_k (the derivatives of eq. (8) of
    !! body_rates_and_gradient); the rates do not move it.
    pure function point_gradient(p, bp, q, view, y) result(g)
        type(pendulum_t), intent(in) :: p       !! the scaled pendulum
        real(dp), intent(in) :: bp              !! b' (m)
        real(dp), intent(in) :: q(3)            !! the point in the principal axes (m)
        integer, intent(in) :: view             !! VIEW_BELOW or VIEW_SIDE
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp) :: g(NSTATE, 2)
        real(dp) :: n(3, 3), dn(3, 3), a(3), zeta, s1, c1, s4, c4, s5, c5
        s1 = sin(y(1))
        c1 = cos(y(1))
        s4 = sin(y(4))
        c4 = cos(y(4))
        s5 = sin(y(5))
        c5 = cos(y(5))
        call frame(body_pose(y(1), y(4), y(5), 0.0_dp), n)
        zeta = sqrt(max(tiny(1.0_dp), 1.0_dp - y(2)**2 - y(3)**2))
        a = p%r*[sin(p%lambda), 0.0_dp, -cos(p%lambda)] + matmul(transpose(p%btilde), q)/bp
        g = 0.0_dp
        g(2, :) = seen(bp*p%big_l*[1.0_dp, 0.0_dp, y(2)/zeta], view)
        g(3, :) = seen(bp*p%big_l*[0.0_dp, 1.0_dp, y(3)/zeta], view)
        ! theta1 turns the rows: ntilde_1' = ntilde_2, ntilde_2' = -ntilde_1
        dn = 0.0_dp
        dn(1, :) = n(2, :)
        dn(2, :) = -n(1, :)
        g(1, :) = seen(bp*matmul(a, dn), view)
        ! theta4 the columns: n(:, 1)' = n(:, 2), n(:, 2)' = -n(:, 1)
        dn(:, 1) = n(:, 2)
        dn(:, 2) = -n(:, 1)
        dn(:, 3) = 0.0_dp
        g(4, :) = seen(bp*matmul(a, dn), view)
        ! theta5 each entry's own
        dn(1, :) = [c1*s4*c5, c1*c4*c5, c1*s5]
        dn(2, :) = [-s1*s4*c5, -s1*c4*c5, -s1*s5]
        dn(3, :) = [s4*s5, c4*s5, -c5]
        g(5, :) = seen(bp*matmul(a, dn), view)
    end function point_gradient

    !> The two components of a position the camera of view sees.
    pure function seen(pos, view) result(x)
        real(dp), intent(in) :: pos(3)
        integer, intent(in) :: view
        real(dp) :: x(2)
        if (view == VIEW_SIDE) then
            x = pos(2:3)
        else
            x = pos(1:2)
        end if
    end function seen

    !> The change of the point's position (less its position at zero angles) along each
    !! column of a run at the fixed state y (the rig's own part: b', L, B, r, lambda,
    !! btilde), central differences of the pendulums moved (record_sink_t): d(2, ns).
    pure function point_partial(sink, y) result(d)
        type(record_sink_t), intent(in) :: sink
        real(dp), intent(in) :: y(NSTATE)
        real(dp) :: d(2, sink%ns)
        real(dp) :: z(NSTATE)
        integer :: c
        z = 0.0_dp
        do c = 1, sink%ns
            d(:, c) = ((point_position(sink%pp(c), sink%bpp(c), sink%q, sink%view, y) - &
                        point_position(sink%pp(c), sink%bpp(c), sink%q, sink%view, z)) - &
                       (point_position(sink%pm(c), sink%bpm(c), sink%q, sink%view, y) - &
                        point_position(sink%pm(c), sink%bpm(c), sink%q, sink%view, z)))/ &
                      (2.0_dp*sink%hc(c))
        end do
    end function point_partial

    !> theta4 (rad) or W = omega . n3 (rad per unit tau) of a chart state.
    pure real(dp) function output_value(rate, y) result(v)
        logical, intent(in) :: rate
        real(dp), intent(in) :: y(NSTATE)
        if (rate) then
            v = vertical_rate(y)
        else
            v = y(4)
        end if
    end function output_value

    !> The gradient of output_value with respect to the chart state.
    pure function output_gradient(rate, y) result(g)
        logical, intent(in) :: rate
        real(dp), intent(in) :: y(NSTATE)
        real(dp) :: g(NSTATE)
        if (rate) then
            g = vertical_rate_gradient(y)
        else
            g = 0.0_dp
            g(4) = 1.0_dp
        end if
    end function output_gradient

    !> The rates an instrument fixed on the body reads at a chart state (rad per unit tau):
    !! w(k) = axes(k, :) . omega_b, omega_b the body's angular velocity in its principal
    !! axes b_i (b = btilde n, eq. (11)), omega = Omega_1 theta1' - n3 theta4' + Omega_5
    !! theta5' (eq. (14)); the cable's direction does not turn the body.
    pure function body_rates(btilde, axes, y) result(w)
        real(dp), intent(in) :: btilde(3, 3)    !! the principal axes in ntilde (eq. (9))
        real(dp), intent(in) :: axes(3, 3)      !! rows: the instrument's axes in b_i
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp) :: w(3)
        real(dp) :: n(3, 3), b(3, 3), omb(3)
        call frame(body_pose(y(1), y(4), y(5), 0.0_dp), n)
        b = matmul(btilde, n)
        ! b_i . ntilde_3 = btilde(i, 3); b_i . n_3 = b(i, 3); b_i . (c4 n1 - s4 n2)
        omb = btilde(:, 3)*y(6) - b(:, 3)*y(9) + (cos(y(4))*b(:, 1) - sin(y(4))*b(:, 2))*y(10)
        w = matmul(axes, omb)
    end function body_rates

    !> The gradient of body_rates with respect to the chart state, g(:, k) for axis k
    !! (body_rates_and_gradient).
    pure function body_rates_gradient(btilde, axes, y) result(g)
        real(dp), intent(in) :: btilde(3, 3), axes(3, 3)
        real(dp), intent(in) :: y(NSTATE)
        real(dp) :: g(NSTATE, 3)
        real(dp) :: w(3)
        call body_rates_and_gradient(btilde, axes, y, w, g)
    end function body_rates_gradient

    !> body_rates (w) and their gradient g(:, k) with respect to the chart state: linear in
    !! theta1', theta4', theta5'; the angles' columns from the derivatives of the direction
    !! cosines of eq. (8) (theta1 turns the rows: n1' = n2, n2' = -n1; theta4 the columns:
    !! n(:, 1)' = n(:, 2), n(:, 2)' = -n(:, 1); theta5 each entry's own), through b = btilde n.
    pure subroutine body_rates_and_gradient(btilde, axes, y, w, g)
        real(dp), intent(in) :: btilde(3, 3), axes(3, 3)
        real(dp), intent(in) :: y(NSTATE)
        real(dp), intent(out) :: w(3), g(NSTATE, 3)
        real(dp) :: n(3, 3), b(3, 3), dn(3, 3), e(3), om(3)
        real(dp) :: s1, c1, s4, c4, s5, c5
        s1 = sin(y(1))
        c1 = cos(y(1))
        s4 = sin(y(4))
        c4 = cos(y(4))
        s5 = sin(y(5))
        c5 = cos(y(5))
        call frame(body_pose(y(1), y(4), y(5), 0.0_dp), n)
        b = matmul(btilde, n)
        e = c4*b(:, 1) - s4*b(:, 2)
        om = btilde(:, 3)*y(6) - b(:, 3)*y(9) + e*y(10)
        w = matmul(axes, om)
        g = 0.0_dp
        g(6, :) = matmul(axes, btilde(:, 3))
        g(9, :) = -matmul(axes, b(:, 3))
        g(10, :) = matmul(axes, e)
        ! theta1
        dn = 0.0_dp
        dn(1, :) = n(2, :)
        dn(2, :) = -n(1, :)
        g(1, :) = angle_column(dn, 0.0_dp)
        ! theta4
        dn(:, 1) = n(:, 2)
        dn(:, 2) = -n(:, 1)
        dn(:, 3) = 0.0_dp
        g(4, :) = angle_column(dn, 1.0_dp)
        ! theta5
        dn(1, :) = [c1*s4*c5, c1*c4*c5, c1*s5]
        dn(2, :) = [-s1*s4*c5, -s1*c4*c5, -s1*s5]
        dn(3, :) = [s4*s5, c4*s5, -c5]
        g(5, :) = angle_column(dn, 0.0_dp)
    contains
        !> The rates' change along an angle that changes n by dn (and, with e4 = 1, theta4
        !! itself in the factors c4, s4 of Omega_5).
        pure function angle_column(dnn, e4) result(col)
            real(dp), intent(in) :: dnn(3, 3), e4
            real(dp) :: col(3), dbb(3, 3)
            dbb = matmul(btilde, dnn)
            col = matmul(axes, -dbb(:, 3)*y(9) + (c4*dbb(:, 1) - s4*dbb(:, 2) &
                                                 - e4*(s4*b(:, 1) + c4*b(:, 2)))*y(10))
        end function angle_column
    end subroutine body_rates_and_gradient

    !> The values a sink takes from a chart state (v) and their gradients (g(:, k)): theta4
    !! or W (one), or the instrument's three rates.
    pure subroutine sink_outputs(sink, y, v, g)
        type(record_sink_t), intent(in) :: sink
        real(dp), intent(in) :: y(NSTATE)
        real(dp), intent(out) :: v(:), g(:, :)
        if (sink%point) then
            v = point_position(sink%p, sink%bp, sink%q, sink%view, y) - &
                point_position(sink%p, sink%bp, sink%q, sink%view, spread(0.0_dp, 1, NSTATE))
            g = point_gradient(sink%p, sink%bp, sink%q, sink%view, y)
        else if (sink%rates) then
            call body_rates_and_gradient(sink%btilde, sink%axes, y, v, g)
        else
            v(1) = output_value(sink%rate, y)
            g(:, 1) = output_gradient(sink%rate, y)
        end if
    end subroutine sink_outputs

    !> One sample of the model (record_sink_t), with its sensitivities when carried.
    subroutine record_take(sink, m, k, t, y, stat)
        class(record_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k                !! sample (from 0)
        real(dp), intent(in) :: t               !! its tau
        real(dp), intent(in) :: y(:)            !! chart state there
        type(status_t), intent(out) :: stat
        real(dp) :: g(NSTATE, sink%nout), f(NSTATE), v(sink%nout)
        stat%code = 0
        if (sink%ns == 0 .and. .not. sink%shift) then
            if (sink%point) then
                sink%vals(:, k) = point_position(sink%p, sink%bp, sink%q, sink%view, &
                                                 y(1:NSTATE)) - point_position(sink%p, &
                                  sink%bp, sink%q, sink%view, spread(0.0_dp, 1, NSTATE))
            else if (sink%rates) then
                sink%vals(:, k) = body_rates(sink%btilde, sink%axes, y(1:NSTATE))
            else
                sink%vals(1, k) = output_value(sink%rate, y(1:NSTATE))
            end if
            return
        end if
        call sink_outputs(sink, y(1:NSTATE), v, g)
        sink%vals(:, k) = v
        select type (m)
        type is (kane_run_t)
            if (sink%ns > 0) then
                if (sink%nout == 1) then
                    call m%sens_dot_at(t, g(:, 1), sink%dvals(:, 1, k), stat)
                else
                    ! the three axes share the dense output's interpolation
                    call m%sens_dots_at(t, g, sink%dvals(:, :, k), stat)
                end if
            end if
            if (stat%code == 0 .and. sink%point .and. sink%ns > 0) &
                sink%dvals(:, :, k) = sink%dvals(:, :, k) + &
                                      transpose(point_partial(sink, y(1:NSTATE)))
            if (stat%code == 0 .and. sink%shift) then
                call m%slope_at(t, f, stat)
                sink%slope(:, k) = matmul(f, g)
            end if
        end select
        if (stat%code /= 0) stat%msg = stat%msg//' at tau = '//sci(t)
    end subroutine record_take

    !> The model at the point pt over the samples t (a fit's window), with its derivatives
    !! along the quantities fit (the fit's parameters but the bias; none: the values alone):
    !! from the last run when it was of the same point and reached those samples (with the
    !! derivatives when asked), else from a run, which is kept.  A run of the whole record
    !! with derivatives after a point whose gain was within CARRY_GAIN carries the budget's
    !! inputs too; one that does not runs the model alone and takes the derivatives of the
    !! last whole-record point where they were computed, when that point's gain was within
    !! REUSE_GAIN (fresh .false.).  Neither with the sensitivities in the error control.
    subroutine values(self, pt, t, whole, fit, vals, dv, stat, fresh)
        class(record_runs_t), intent(inout) :: self
        type(run_point_t), intent(in) :: pt     !! rig, start, release
        real(dp), intent(in) :: t(:)            !! the window's sample times (s)
        logical, intent(in) :: whole            !! the window is the whole record
        type(run_columns_t), intent(in) :: fit  !! the fit's parameters differentiated
        real(dp), allocatable, intent(out) :: vals(:), dv(:, :)
        type(status_t), intent(out) :: stat
        logical, intent(out), optional :: fresh     !! dv computed at pt (not taken again)
        type(run_columns_t) :: cols, none
        real(dp), allocatable :: dall(:, :)
        integer :: m, nfit, nx, mv
        logical :: derivs, reuse
        stat%code = 0
        if (present(fresh)) fresh = .true.
        m = size(t)
        mv = runs_nout(self)*m                  ! the values: nout blocks of the samples
        nfit = size(fit%names)
        derivs = nfit > 0
        if (derivs) then
            self%jac_fresh = .true.
            self%last_whole = whole
            if (allocated(self%fresh_dv)) deallocate (self%fresh_dv)
        else
            self%last_whole = .false.
        end if
        if (self%valid .and. self%n >= m .and. (self%nfit == nfit .or. .not. derivs) .and. &
            (.not. (self%rates .or. self%point) .or. self%n == m)) then
            if (same_point(self%key, pt)) then
                vals = self%v(1:mv)
                dv = self%dv(1:mv, 1:nfit)
                if (derivs .and. whole) self%fresh_dv = dv
                return
            end if
        end if
        nx = 0
        reuse = .false.
        cols = fit
        if (derivs .and. whole .and. .not. self%acc%sens_error_control) then
            if (self%whole_gain <= CARRY_GAIN .and. allocated(self%x)) then
                cols%names = [character(len=16) :: fit%names, self%carry%names]
                cols%xs = [fit%xs, self%carry%xs]
                nx = size(self%carry%names)
            else if (allocated(self%jac_dv) .and. self%jac_gain <= REUSE_GAIN) then
                reuse = size(self%jac_dv, 1) == mv .and. size(self%jac_dv, 2) == nfit
            end if
        end if
        if (reuse) then
            ! the model alone; its derivatives those of the last whole-record point
            allocate (vals(mv), dall(mv, 0), none%names(0), none%xs(0))
            call self%run(pt, t, none, vals, dall, stat)
            self%valid = .false.
            if (stat%code /= 0) return
            dv = self%jac_dv
            if (present(fresh)) fresh = .false.
            self%jac_fresh = .false.
            call keep(self, pt, m, 0, 0, vals, dall)
            return
        end if
        allocate (vals(mv), dall(mv, size(cols%names)))
        call self%run(pt, t, cols, vals, dall, stat)
        self%valid = .false.
        if (stat%code /= 0) return
        dv = dall(:, 1:nfit)
        if (derivs .and. whole) self%fresh_dv = dv
        call keep(self, pt, m, nfit, nx, vals, dall)
    end subroutine values

    !> The run kept: its point, samples, columns, values and derivatives.
    subroutine keep(self, pt, n, nfit, nx, v, dv)
        type(record_runs_t), intent(inout) :: self
        type(run_point_t), intent(in) :: pt
        integer, intent(in) :: n, nfit, nx
        real(dp), intent(in) :: v(:), dv(:, :)
        self%valid = .true.
        self%key = pt
        self%n = n
        self%nfit = nfit
        self%nx = nx
        self%v = v
        self%dv = dv
    end subroutine keep

    !> The estimator's Gauss-Newton gain at the point just evaluated with derivatives: kept
    !! for a whole-record point (whole_gain), and with its derivatives when they were
    !! computed there (jac_gain, jac_dv).
    subroutine note_gain(self, gain)
        class(record_runs_t), intent(inout) :: self
        real(dp), intent(in) :: gain
        if (.not. self%last_whole) return
        self%last_whole = .false.
        self%whole_gain = gain
        if (allocated(self%fresh_dv)) then
            self%jac_gain = gain
            call move_alloc(self%fresh_dv, self%jac_dv)
        end if
    end subroutine note_gain

    !> The derivatives along the budget's inputs x (ncols of them with u > 0) of the last
    !! run, when it was of the point pt, over at least m samples, and carried these inputs
    !! (the same names, the same values); ok .false. otherwise.
    subroutine carried(self, pt, m, x, ncols, dv, ok)
        class(record_runs_t), intent(in) :: self
        type(run_point_t), intent(in) :: pt
        integer, intent(in) :: m, ncols
        type(input_t), intent(in) :: x(:)
        real(dp), allocatable, intent(out) :: dv(:, :)
        logical, intent(out) :: ok
        integer :: k
        ok = .false.
        if (.not. self%valid .or. self%n < m .or. self%nx /= ncols) return
        if ((self%rates .or. self%point) .and. self%n /= m) return
        if (.not. allocated(self%x)) return
        if (size(self%x) /= size(x)) return
        do k = 1, size(x)
            if (self%x(k)%name /= x(k)%name .or. self%x(k)%value /= x(k)%value .or. &
                (self%x(k)%u > 0.0_dp .neqv. x(k)%u > 0.0_dp)) return
        end do
        ok = same_point(self%key, pt)
        if (ok) dv = self%dv(1:runs_nout(self)*m, self%nfit + 1:)
    end subroutine carried

    !> The kept run and the derivatives to take again dropped, the gain set to 0: the next
    !! whole-record evaluation with derivatives computes them there and carries the budget.
    subroutine forget(self)
        class(record_runs_t), intent(inout) :: self
        self%whole_gain = 0.0_dp
        self%valid = .false.
        if (allocated(self%jac_dv)) deallocate (self%jac_dv)
    end subroutine forget

    !> The budget's inputs x and the columns (names, sizes xs) of those with u > 0.
    subroutine set_carry(self, x, cols)
        class(record_runs_t), intent(inout) :: self
        type(input_t), intent(in) :: x(:)
        type(run_columns_t), intent(in) :: cols
        self%x = x
        self%carry = cols
    end subroutine set_carry

    !> Two points of the record model are the same: the same rig, start and release (by
    !! value).
    pure logical function same_point(a, b)
        type(run_point_t), intent(in) :: a, b
        same_point = a%t0 == b%t0
        if (same_point) same_point = same_rig(a%rg, b%rg)
        if (same_point) same_point = same_start(a%st, b%st)
    end function same_point

    !> The rig and start with the parameters p of the fit set (I1, c_v, c_q, amplitude, I2,
    !! I3, cg_depth, tilt, sway), t0 and the bias of each value of a sample.
    subroutine apply_parameters(prob, p, rg, st, t0, bias, scale)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: p(:)
        type(rig_t), intent(out) :: rg
        type(start_t), intent(out) :: st
        real(dp), intent(out) :: t0, bias(3)
        real(dp), intent(out), optional :: scale(3)     !! the record's scale of each value
        integer :: j
        rg = prob%rg
        st = prob%st
        t0 = prob%t0
        bias = prob%bias
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
            case (P_T0)
                t0 = p(j)
            case (P_I2)
                rg%inertia(2) = p(j)
            case (P_I3)
                rg%inertia(3) = p(j)
            case (P_CG)
                call set_input(rg, st, 'cg_depth', p(j))
            case (P_TILT)
                st%tilt = p(j)
            case (P_SWAY)
                st%sway = p(j)
            case (P_BIAS_Y)
                bias(2) = p(j)
            case (P_BIAS_Z)
                bias(3) = p(j)
            case (P_SCALE, P_SCALE_Y, P_SCALE_Z)
                continue
            case default
                bias(1) = p(j)
            end select
        end do
        ! the release's way ('rates', 'point'): the amplitude of the deck or the fit is a size
        if (prob%turn /= 1.0_dp) st%amplitude = prob%turn*st%amplitude
        if (present(scale)) then
            scale = prob%scale
            do j = 1, prob%np
                select case (prob%which(j))
                case (P_SCALE)
                    scale(1) = p(j)
                    if (prob%point) scale(2) = p(j)
                case (P_SCALE_Y)
                    scale(2) = p(j)
                case (P_SCALE_Z)
                    scale(3) = p(j)
                end select
            end do
        end if
    end subroutine apply_parameters

    !> The derivatives dv (a column each of names) along the model's start amplitude as
    !! derivatives along its size: the column 'amplitude' times the release's turn.
    pure subroutine turn_columns(prob, names, dv)
        type(record_fit_t), intent(in) :: prob
        character(len=*), intent(in) :: names(:)
        real(dp), intent(inout) :: dv(:, :)
        integer :: c
        do c = 1, min(size(names), size(dv, 2))
            if (trim(names(c)) == 'amplitude') dv(:, c) = prob%turn*dv(:, c)
        end do
    end subroutine turn_columns

    !> A scale parameter (of the record's values or of an instrument axis).
    elemental logical function is_scale(which)
        integer, intent(in) :: which
        is_scale = which == P_SCALE .or. which == P_SCALE_Y .or. which == P_SCALE_Z
    end function is_scale

    !> The model's values (and derivatives) over the record's scale of each value: block k
    !! of vals (and the rows of dv) divided by scale(k).
    pure subroutine apply_scale(prob, scale, vals, dv)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: scale(3)
        real(dp), intent(inout) :: vals(:), dv(:, :)
        integer :: m, k
        m = size(vals)/prob%nout
        do k = 1, prob%nout
            vals((k - 1)*m + 1:k*m) = vals((k - 1)*m + 1:k*m)/scale(k)
            dv((k - 1)*m + 1:k*m, :) = dv((k - 1)*m + 1:k*m, :)/scale(k)
        end do
    end subroutine apply_scale

    !> The names of the estimated parameters (for the estimator's messages).
    pure function estimated_names(prob) result(names)
        type(record_fit_t), intent(in) :: prob
        character(len=16) :: names(prob%np)
        integer :: j
        do j = 1, prob%np
            names(j) = PARAM_NAMES(prob%which(j))
            if (prob%which(j) == P_BIAS .and. (prob%rates .or. prob%point)) names(j) = 'bias_x'
            if (prob%which(j) == P_SCALE .and. prob%rates) names(j) = 'scale_x'
        end do
    end function estimated_names

    !> The number of residuals of the problem: the samples ifirst .. nuse (each value of a
    !! sample: nout blocks).
    pure integer function record_nres(prob) result(n)
        class(record_fit_t), intent(in) :: prob
        n = prob%nout*(prob%nuse - prob%ifirst + 1)
    end function record_nres

    !> The measured values of the samples ifirst .. nuse, stacked as the residuals are (nout
    !! blocks, one per value of a sample).
    pure function stacked_values(prob) result(v)
        type(record_fit_t), intent(in) :: prob
        real(dp), allocatable :: v(:)
        integer :: i0, i1, n
        i0 = prob%ifirst
        i1 = prob%nuse
        if (prob%rates) then
            n = size(prob%rec%t)
            v = [prob%rec%vs(i0:i1), prob%rec%vs(n + i0:n + i1), prob%rec%vs(2*n + i0:2*n + i1)]
        else if (prob%point) then
            n = size(prob%rec%t)
            v = [prob%rec%vs(i0:i1), prob%rec%vs(n + i0:n + i1)]
        else
            v = prob%rec%v(i0:i1)
        end if
    end function stacked_values

    !> The weights of the residuals (1/u_i times the robust weights' roots), stacked.
    pure function stacked_weights(prob) result(w)
        type(record_fit_t), intent(in) :: prob
        real(dp), allocatable :: w(:)
        integer :: i0, i1
        i0 = prob%ifirst
        i1 = prob%nuse
        w = prob%w(i0:i1)*prob%hw(i0:i1)
        if (prob%nout == 3) w = [w, w, w]
        if (prob%nout == 2) w = [w, w]
    end function stacked_weights

    !> The bias of each residual, stacked (bias(k) over block k).
    pure function stacked_bias(prob, bias) result(b)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: bias(3)
        real(dp), allocatable :: b(:)
        integer :: m, k
        m = prob%nuse - prob%ifirst + 1
        allocate (b(prob%nout*m))
        do k = 1, prob%nout
            b((k - 1)*m + 1:k*m) = bias(k)
        end do
    end function stacked_bias

    !> Residuals (sign model + bias - measured)/u_i (times the robust weights' roots) over
    !! the samples ifirst .. nuse.  A parameter set the model cannot take (I1 <= 0, an
    !! amplitude outside 0 .. 180 degrees, a cable slack, ...) is a failed evaluation.
    subroutine record_residual(prob, p, r, stat)
        class(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        real(dp) :: bias(3)
        real(dp), allocatable :: vals(:), dv(:, :)
        r = 0.0_dp
        call model_values(prob, p, .false., vals, dv, bias, stat)
        if (stat%code /= 0) return
        r = (prob%sign*vals + stacked_bias(prob, bias) - stacked_values(prob))*stacked_weights(prob)
        if (.not. all_finite(r)) call set_error(stat, ERR_NUMERIC, 'non-finite model values')
    end subroutine record_residual

    !> The problem has its own Jacobian with forward sensitivities (&integration
    !! sensitivities = 'forward').
    logical function record_has_jacobian(prob)
        class(record_fit_t), intent(in) :: prob
        record_has_jacobian = prob%acc%sensitivities == SENS_FORWARD
    end function record_has_jacobian

    !> The residuals (record_residual) and their Jacobian dr/dp from one run with the
    !! forward sensitivities of the estimated parameters (record_model_sens; the bias's
    !! column is the weights).
    subroutine record_residual_jacobian(prob, p, r, jac, stat)
        class(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:), jac(:, :)
        type(status_t), intent(out) :: stat
        real(dp) :: bias(3), scale(3), t0
        real(dp), allocatable :: vals(:), dv(:, :), w(:)
        type(rig_t) :: rg
        type(start_t) :: st
        integer :: j, c, m, k
        r = 0.0_dp
        jac = 0.0_dp
        call model_values(prob, p, .true., vals, dv, bias, stat)
        if (stat%code /= 0) return
        w = stacked_weights(prob)
        m = prob%nuse - prob%ifirst + 1
        r = (prob%sign*vals + stacked_bias(prob, bias) - stacked_values(prob))*w
        c = 0
        if (any(is_scale(prob%which(1:prob%np)))) call apply_parameters(prob, p, rg, st, t0, &
                                                                      bias, scale)
        do j = 1, prob%np
            if (is_bias(prob%which(j))) then
                k = bias_axis(prob%which(j))
                jac((k - 1)*m + 1:k*m, j) = w((k - 1)*m + 1:k*m)
            else if (is_scale(prob%which(j))) then
                ! the model over the scale: its change -model/scale, over each value it scales
                do k = 1, prob%nout
                    if (scale_of(prob, prob%which(j), k)) jac((k - 1)*m + 1:k*m, j) = &
                        -prob%sign*vals((k - 1)*m + 1:k*m)/scale(k)*w((k - 1)*m + 1:k*m)
                end do
            else
                c = c + 1
                jac(:, j) = prob%sign*dv(:, c)*w
            end if
        end do
        if (.not. all_finite(r) .or. .not. all(ieee_is_finite(jac))) then
            call set_error(stat, ERR_NUMERIC, 'non-finite model values')
            return
        end if
    end subroutine record_residual_jacobian

    !> Whether the scale parameter which scales value k of a sample.
    pure logical function scale_of(prob, which, k)
        type(record_fit_t), intent(in) :: prob
        integer, intent(in) :: which, k
        select case (which)
        case (P_SCALE)
            scale_of = k == 1 .or. (prob%point .and. k == 2)
        case (P_SCALE_Y)
            scale_of = k == 2
        case default
            scale_of = k == 3
        end select
    end function scale_of

    !> A bias parameter (of the value or of an instrument axis).
    pure logical function is_bias(which)
        integer, intent(in) :: which
        is_bias = which == P_BIAS .or. which == P_BIAS_Y .or. which == P_BIAS_Z
    end function is_bias

    !> The value (axis) a bias parameter offsets: 1, 2, 3.
    pure integer function bias_axis(which)
        integer, intent(in) :: which
        bias_axis = 1
        if (which == P_BIAS_Y) bias_axis = 2
        if (which == P_BIAS_Z) bias_axis = 3
    end function bias_axis

    !> The estimator's Gauss-Newton gain at the point just evaluated: to the evaluator
    !! (whether the next whole-record run carries the budget, or takes this Jacobian again).
    subroutine record_note_gain(prob, gain)
        class(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: gain
        call prob%runs%note_gain(gain)
    end subroutine record_note_gain

    !> The residuals and the Jacobian at p computed there (carrying the budget's inputs),
    !! and its Gauss-Newton gain (told the evaluator): for a fit that ended on a Jacobian
    !! taken again from an earlier point (runs%jac_fresh false), whose covariance and
    !! budget need it at the estimate.
    subroutine fresh_jacobian(prob, p, r, jac, stat, gain)
        type(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        real(dp), intent(out) :: r(:), jac(:, :)
        type(status_t), intent(out) :: stat
        real(dp), intent(out), optional :: gain !! its Gauss-Newton gain
        real(dp) :: g
        call prob%runs%forget()
        call record_residual_jacobian(prob, p, r, jac, stat)
        if (stat%code /= 0) return
        g = gauss_newton_gain(r, jac)
        call prob%note_gain(g)
        if (present(gain)) gain = g
    end subroutine fresh_jacobian

    !> The budget's inputs x: a run of the whole record near the minimum carries the
    !! derivatives of those with u > 0 beside the fit's (set after the problem's rig).
    subroutine carry_inputs(prob, x)
        type(record_fit_t), intent(inout) :: prob
        type(input_t), intent(in) :: x(:)
        type(run_columns_t) :: cols
        allocate (cols%names(0), cols%xs(0))
        call budget_columns(prob, x, cols%names, cols%xs)
        call prob%runs%set_carry(x, cols)
    end subroutine carry_inputs

    !> The model at the parameters p over the samples ifirst .. nuse (vals), with its
    !! derivatives along the estimated parameters but the bias when `derivs` (dv, a column
    !! each), and the bias; through the problem's evaluator (record_runs_t%values: the last
    !! run reused, the budget carried, derivatives taken again; fresh .false. when they
    !! were).  A parameter set the model cannot take (I1 <= 0, an amplitude outside 0 .. 180
    !! degrees) is a failed evaluation.
    subroutine model_values(prob, p, derivs, vals, dv, bias, stat, fresh)
        type(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        logical, intent(in) :: derivs
        real(dp), allocatable, intent(out) :: vals(:), dv(:, :)
        real(dp), intent(out) :: bias(3)
        type(status_t), intent(out) :: stat
        logical, intent(out), optional :: fresh     !! dv computed at p (not taken again)
        type(run_point_t) :: pt
        type(run_columns_t) :: fit
        real(dp) :: scale(3)
        integer :: i0, i1, j, m
        stat%code = 0
        if (present(fresh)) fresh = .true.
        call apply_parameters(prob, p, pt%rg, pt%st, pt%t0, bias, scale)
        i0 = prob%ifirst
        i1 = prob%nuse
        m = i1 - i0 + 1
        if (.not. (pt%rg%inertia(1) > 0.0_dp) .or. .not. (prob%turn*pt%st%amplitude > &
            0.0_dp .and. prob%turn*pt%st%amplitude < 180.0_dp) .or. .not. all(pt%rg%inertia > 0.0_dp) .or. &
            .not. (abs(pt%st%tilt) < 0.5_dp*pi .and. abs(pt%st%sway) < 0.5_dp*pi)) then
            allocate (vals(prob%nout*m), dv(prob%nout*m, 0))
            vals = 0.0_dp
            call set_error(stat, ERR_NUMERIC, 'parameters out of the model''s range')
            return
        end if
        allocate (fit%names(0), fit%xs(0))
        if (derivs) then
            do j = 1, prob%np
                if (is_bias(prob%which(j)) .or. is_scale(prob%which(j))) cycle
                fit%names = [character(len=16) :: fit%names, PARAM_NAMES(prob%which(j))]
                fit%xs = [fit%xs, prob%xs(j)]
            end do
        end if
        ! the evaluator runs the problem's model: its accuracy and its quantity
        prob%runs%acc = prob%acc
        prob%runs%rate = prob%rate
        prob%runs%rates = prob%rates
        prob%runs%axes = prob%axes
        prob%runs%point = prob%point
        prob%runs%q = prob%q
        prob%runs%view = prob%view
        call prob%runs%values(pt, prob%rec%t(i0:i1), i1 == size(prob%rec%t), fit, vals, dv, &
                              stat, fresh)
        ! the runs' derivative along the model's amplitude: along its size, times the turn
        if (stat%code == 0 .and. derivs .and. prob%turn /= 1.0_dp) &
            call turn_columns(prob, fit%names, dv)
        ! the record's scale: the model of a value is the quantity over it
        if (stat%code == 0 .and. (prob%point .or. any(scale /= 1.0_dp))) &
            call apply_scale(prob, scale, vals, dv)
    end subroutine model_values
    !> The names and sizes of the budget's inputs with u > 0 (x), appended to names and xs.
    pure subroutine budget_columns(prob, x, names, xs)
        type(record_fit_t), intent(in) :: prob
        type(input_t), intent(in) :: x(:)
        character(len=16), allocatable, intent(inout) :: names(:)
        real(dp), allocatable, intent(inout) :: xs(:)
        integer :: j
        do j = 1, size(x)
            if (.not. (x(j)%u > 0.0_dp)) cycle
            names = [character(len=16) :: names, x(j)%name]
            xs = [xs, input_size(prob, x(j))]
        end do
    end subroutine budget_columns

    !> Where the release is in a record (the start values of t0, the amplitude, the bias and
    !! the sign).  The first tenth of the record (at least 10 samples, at most 200) gives a
    !! level and its noise (median and scaled median absolute deviation); the first sample
    !! beyond max(6 noise, 5 % of the largest excursion) from that level is where the motion
    !! shows.  When it shows after half that quiet stretch, the body was held still: the
    !! release is at the last quiet sample, and the held samples stay in the fit (they fix
    !! the bias).  Otherwise the record starts mid-swing: it is fitted from its first turning
    !! point (an angle's first extreme about its centre, a rate's first crossing of its
    !! mean), where the body is at rest for an instant.  The amplitude: the held angle's
    !! distance from the swing's centre, or a rate's first peak over 2 pi / T; the sign: +1
    !! when the first swing goes the way the model's does (theta4 falling from +A, W rising
    !! from 0).
    subroutine find_release(rec, rate, rl)
        type(record_t), intent(in) :: rec
        logical, intent(in) :: rate             !! W (rad/s), else theta4 (rad)
        type(record_start_t), intent(out) :: rl
        real(dp) :: v(size(rec%v))
        real(dp) :: level, noise, vmax, thr, centre, peak, tp
        integer :: n, k, idep, i, ic, ie, j
        n = size(rec%v)
        v = rec%v
        k = max(10, min(200, n/10))
        k = min(k, n)
        level = median(v(1:k))
        noise = 1.4826_dp*median(abs(v(1:k) - level))
        vmax = maxval(abs(v - level))
        thr = max(6.0_dp*noise, 0.05_dp*vmax)
        idep = n
        do i = 1, n
            if (abs(v(i) - level) > thr) then
                idep = i
                exit
            end if
        end do
        rl%held = idep > k/2 .and. idep < n
        if (rl%held) then
            rl%ifirst = 1
            rl%t0 = rec%t(max(1, idep - 1))
            rl%level = level
            centre = sum(v(idep:))/(n - idep + 1)
            tp = mean_period(rec, idep)
            rl%period = tp
            if (rate) then
                ! the model's W = omega . n3 is positive first (theta4 falls from +A: W is
                ! -theta4' to first order)
                rl%sign = merge(1.0_dp, -1.0_dp, v(idep) > level)
                peak = maxval(abs(v(idep:min(n, idep + first_span(tp))) - level))
                rl%amplitude = amplitude_of_rate(peak, tp)
            else
                rl%sign = merge(1.0_dp, -1.0_dp, level > centre)
                rl%amplitude = abs(level - centre)/deg
                rl%level = centre               ! the angle's zero: the swing's centre
            end if
        else
            ! mid-swing: the first turning point
            centre = sum(v)/n
            tp = mean_period(rec)
            rl%period = tp
            ic = first_crossing(v, centre, 1)
            if (rate) then
                ie = max(1, ic)
                ! W rising through its mean: theta4 at a maximum, the model's release
                rl%sign = merge(1.0_dp, -1.0_dp, v(min(n, ie + 1)) > v(max(1, ie - 1)))
                peak = maxval(abs(v(ie:min(n, ie + first_span(tp))) - centre))
                rl%amplitude = amplitude_of_rate(peak, tp)
            else
                ! the extreme before the first crossing when it is inside, else the next one
                ie = maxloc(abs(v(1:max(1, ic)) - centre), 1)
                if (ie <= 1 .or. ic <= 0) then
                    j = first_crossing(v, centre, max(1, ic) + 1)
                    if (j <= 0) j = n
                    ie = max(1, ic) - 1 + maxloc(abs(v(max(1, ic):j) - centre), 1)
                end if
                rl%sign = merge(1.0_dp, -1.0_dp, v(ie) > centre)
                rl%amplitude = abs(v(ie) - centre)/deg
            end if
            rl%ifirst = max(1, ie)
            rl%t0 = rec%t(rl%ifirst)
            rl%level = centre
        end if
        rl%amplitude = max(1.0e-3_dp, min(179.0_dp, rl%amplitude))
    contains
        !> Samples in about half a period (the first swing), at least 3.
        integer function first_span(t)
            real(dp), intent(in) :: t
            first_span = 3
            if (t > 0.0_dp .and. n > 1) first_span = max(3, nint(0.5_dp*t/ &
                ((rec%t(n) - rec%t(1))/(n - 1))))
        end function first_span
        !> A rate's peak over 2 pi / T as an amplitude (degrees), small-amplitude motion.
        real(dp) function amplitude_of_rate(pk, t)
            real(dp), intent(in) :: pk, t
            amplitude_of_rate = 10.0_dp
            if (t > 0.0_dp) amplitude_of_rate = pk*t/(2.0_dp*pi)/deg
        end function amplitude_of_rate
        !> The first sample from i0 on where v crosses c, after having been a tenth of the
        !! largest excursion away from it (0 when none).
        integer function first_crossing(x, c, i0)
            real(dp), intent(in) :: x(:), c
            integer, intent(in) :: i0
            real(dp) :: band
            integer :: ii, side
            first_crossing = 0
            band = 0.1_dp*maxval(abs(x - c))
            side = 0
            do ii = max(2, i0), size(x)
                if (x(ii - 1) - c < -band) side = -1
                if (x(ii - 1) - c > band) side = 1
                if ((side == -1 .and. x(ii) >= c) .or. (side == 1 .and. x(ii) <= c)) then
                    first_crossing = ii
                    return
                end if
            end do
        end function first_crossing
    end subroutine find_release

    !> Whether a record is the quantity the deck says, where it shows the release from rest
    !! (&start mode = 'raised'): an angle is there at its extreme, a rate (W = 0) at its
    !! centre.  It shows the release when its times count from it and its first sample is
    !! within a twentieth of its period after t = 0 (t0 not estimated), or when the body was
    !! held still before it (find_release, t0 estimated).  A rate that stands there more
    !! than 0.6 of its largest swing from its centre, or an angle less than 0.2, is refused
    !! (ERR_DECK naming quantity and record_units).  A tracked point (quantity 'point',
    !! lengths) is no angle or rate: not checked.  name: the record, for messages.
    subroutine check_record_kind(rec, mea, raised, name, stat)
        type(record_t), intent(in) :: rec
        type(measurement_group_t), intent(in) :: mea    !! (quantity, estimate)
        logical, intent(in) :: raised           !! &start mode = 'raised'
        character(len=*), intent(in) :: name
        type(status_t), intent(out) :: stat
        type(record_start_t) :: rl
        real(dp) :: tp, level, centre, pk, off
        integer :: n, i0
        logical :: rate
        character(len=:), allocatable :: where
        stat%code = STATUS_OK
        ! a tracked point: no angle to mistake for a rate (its coordinates in px or m)
        if (trim(mea%quantity) == 'point') return
        n = size(rec%v)
        if (.not. raised .or. n < 3) return
        rate = trim(mea%quantity) == 'rate' .or. rec%rate
        if (mea%estimated('t0')) then
            call find_release(rec, rate, rl)
            if (.not. rl%held) return
            i0 = count(rec%t <= rl%t0)
            if (i0 < 1 .or. i0 > n - 3) return
            level = median_value(rec%v(1:i0))
            centre = sum(rec%v(i0 + 1:))/(n - i0)
            pk = maxval(abs(rec%v(i0 + 1:) - centre))
            off = abs(level - centre)
            where = 'held still before the release (to t = '//sci(rl%t0, 4)//' s)'
        else
            tp = mean_period(rec)
            if (.not. (tp > 0.0_dp) .or. rec%t(1) > 0.05_dp*tp) return
            centre = median_value(rec%v)
            pk = maxval(abs(rec%v - centre))
            off = abs(rec%v(1) - centre)
            where = 'at the release (its first sample, t = '//sci(rec%t(1), 4)//' s)'
        end if
        if (.not. (pk > 0.0_dp)) return
        if (rate .and. off > 0.6_dp*pk) then
            call set_error(stat, ERR_DECK, name//': '//where//' it stands '// &
                sci(off/rec%to_rad, 3)//' '//trim(rec%units)//' from the centre of its '// &
                'swing, '//itoa(nint(100.0_dp*off/pk))//' % of its largest excursion: a '// &
                'rate released from rest starts at its centre (W = 0), an angle at its '// &
                'extreme; it looks like an angle (theta4); allowed: quantity = ''angle'' '// &
                '(or record_units = ''rad'' or ''deg'') for an angle, a rate (quantity = '// &
                '''rate'', record_units = ''rad/s'' or ''deg/s'') for a gyro''s W')
        else if (.not. rate .and. off < 0.2_dp*pk) then
            call set_error(stat, ERR_DECK, name//': '//where//' it stands '// &
                sci(off/rec%to_rad, 3)//' '//trim(rec%units)//' from the centre of its '// &
                'swing, '//itoa(nint(100.0_dp*off/pk))//' % of its largest excursion: an '// &
                'angle released from rest starts at its extreme, a rate (W = 0) at its '// &
                'centre; it looks like a rate (W); allowed: quantity = ''rate'' (or '// &
                'record_units = ''rad/s'' or ''deg/s'') for a gyro''s W, an angle '// &
                '(quantity = ''angle'', record_units = ''rad'' or ''deg'') for theta4')
        end if
    end subroutine check_record_kind

    !> The median of x.
    function median(x) result(m)
        real(dp), intent(in) :: x(:)
        real(dp) :: m
        real(dp) :: s(size(x)), t
        integer :: i, j, n
        n = size(x)
        s = x
        do i = 2, n                             ! insertion sort: short arrays only
            t = s(i)
            j = i - 1
            do while (j >= 1)
                if (s(j) <= t) exit
                s(j + 1) = s(j)
                j = j - 1
            end do
            s(j + 1) = t
        end do
        if (mod(n, 2) == 1) then
            m = s((n + 1)/2)
        else
            m = 0.5_dp*(s(n/2) + s(n/2 + 1))
        end if
    end function median

    !> The record fit of a deck: the problem (estimated parameters, start values,
    !! difference steps) from the deck and the record.  With t0 estimated, the release is
    !! found in the record (find_release) and gives the start values of t0, the bias and,
    !! when estimated, the amplitude, and the sign; else the times count from the release.
    subroutine fit_problem(rg, st, acc, mea, rec, prob, p0, h, rl)
        type(rig_t), intent(in) :: rg           !! the deck's rig
        type(start_t), intent(in) :: st         !! its start
        type(accuracy_t), intent(in) :: acc     !! its runs' accuracy
        type(measurement_group_t), intent(in) :: mea    !! (seed, quantity, estimate)
        type(record_t), intent(in) :: rec
        type(record_fit_t), intent(out) :: prob
        real(dp), allocatable, intent(out) :: p0(:), h(:)
        type(record_start_t), intent(out), optional :: rl  !! what find_release found
        type(record_start_t) :: rel
        real(dp) :: tp, vscale
        integer :: j, k, n
        logical :: ok
        n = size(rec%t)
        prob%rg = rg
        prob%st = st
        prob%acc = acc
        prob%seed = mea%seed
        prob%rec = rec
        ! a rate by the deck's quantity, or by the unit the record's column names
        prob%rate = trim(mea%quantity) == 'rate' .or. rec%rate
        prob%rates = trim(mea%quantity) == 'rates' .and. allocated(rec%vs)
        if (prob%rates) then
            prob%rate = .true.
            prob%nout = 3
            call parse_axes(mea%record_axes, prob%axes, ok)
            ! the rate about the vertical the instrument's axes give: W = -omega . b_1 at rest
            call vertical_of_rates(prob%rec, prob%axes)
        end if
        prob%point = trim(mea%quantity) == 'point' .and. allocated(rec%vs)
        if (prob%point) then
            ! a tracked point: its two coordinates (rec%vs), the one with the larger swing as
            ! the record's value (its release and period)
            prob%rate = .false.
            prob%nout = 2
            prob%q = mea%record_point
            prob%view = merge(VIEW_SIDE, VIEW_BELOW, trim(mea%record_view) == 'side')
            prob%scale = mea%record_scale
            prob%rec%v = rec%vs(1:n)
            prob%vcol = 1
            if (maxval(rec%vs(n + 1:2*n)) - minval(rec%vs(n + 1:2*n)) > &
                maxval(rec%vs(1:n)) - minval(rec%vs(1:n))) then
                prob%rec%v = rec%vs(n + 1:2*n)
                prob%vcol = 2
            end if
        end if
        prob%t0 = 0.0_dp
        prob%bias = 0.0_dp
        prob%sign = 1.0_dp
        prob%turn = 1.0_dp
        prob%ifirst = 1
        prob%nuse = n
        prob%w = 1.0_dp/rec%u
        allocate (prob%hw(n))
        prob%hw = 1.0_dp
        prob%np = 0
        do k = 1, NPARAM
            if (mea%estimated(PARAM_NAMES(k)) .or. (prob%rates .and. mea%estimated('bias') &
                                                    .and. (k == P_BIAS_Y .or. k == P_BIAS_Z)) &
                .or. (prob%point .and. mea%estimated('bias') .and. k == P_BIAS_Y) .or. &
                (prob%rates .and. mea%estimated('scale') .and. (k == P_SCALE_Y .or. &
                                                                 k == P_SCALE_Z))) then
                prob%np = prob%np + 1
                prob%which(prob%np) = k
            end if
        end do
        if (mea%estimated('t0')) then
            call find_release(prob%rec, prob%rate, rel)
            prob%sign = rel%sign
            prob%ifirst = rel%ifirst
            ! the instrument's rates: no mirror image of the model (tilt and sway keep their
            ! way when the turn reverses): the model released the record's way instead
            if (prob%rates) then
                if (.not. rel%held) call rates_from_rest(prob%rec, rel)
                prob%sign = 1.0_dp
                prob%turn = rel%sign
            end if
            if (prob%point) then
                prob%sign = 1.0_dp
                prob%turn = rel%sign*point_way(prob, rel%period)
            end if
        end if
        if (present(rl)) rl = rel
        allocate (p0(prob%np), h(prob%np))
        prob%xs = 1.0_dp
        tp = mean_period(prob%rec, prob%ifirst)
        if (.not. (tp > 0.0_dp)) tp = rec%t(n) - rec%t(1)
        vscale = max(maxval(abs(prob%rec%v)), tiny(1.0_dp))
        do j = 1, prob%np
            select case (prob%which(j))
            case (P_I1)
                p0(j) = rg%inertia(1)
                h(j) = H_REL*rg%inertia(1)
            case (P_CV)
                p0(j) = rg%c_v
                h(j) = H_REL*max(rg%c_v, DAMP_REF*rg%mass*rg%b_prime*sqrt(rg%g*rg%b_prime))
            case (P_CQ)
                p0(j) = rg%c_q
                h(j) = H_REL*max(rg%c_q, DAMP_REF*rg%mass*rg%b_prime**2)
            case (P_AMP)
                p0(j) = st%amplitude
                if (mea%estimated('t0')) p0(j) = rel%amplitude
                ! a track's excursion is in its units, no angle: the deck's amplitude
                if (prob%point) p0(j) = abs(st%amplitude)
                h(j) = H_REL*max(p0(j), 1.0_dp)
            case (P_T0)
                p0(j) = rel%t0
                h(j) = H_REL*tp
            case (P_I2, P_I3)
                k = prob%which(j) - P_I2 + 2
                p0(j) = rg%inertia(k)
                h(j) = H_REL*rg%inertia(k)
            case (P_CG)
                p0(j) = input_value(rg, st, 'cg_depth')
                h(j) = H_REL*max(abs(p0(j)), 0.1_dp*rg%b_prime)
            case (P_TILT)
                p0(j) = st%tilt
                h(j) = H_REL*max(abs(p0(j)), SMALL_ANGLE)
            case (P_SWAY)
                p0(j) = st%sway
                h(j) = H_REL*max(abs(p0(j)), SMALL_ANGLE)
            case (P_BIAS_Y, P_BIAS_Z)
                p0(j) = 0.0_dp
                ! a point's second coordinate: the camera's origin from the track's mean
                if (prob%point) p0(j) = sum(rec%vs(n + 1:2*n))/n
                h(j) = H_REL*vscale
                if (prob%point) h(j) = H_REL*max(maxval(abs(rec%vs)), tiny(1.0_dp))
            case (P_SCALE, P_SCALE_Y, P_SCALE_Z)
                p0(j) = prob%scale(prob%which(j) - P_SCALE + 1)
                h(j) = H_REL*abs(p0(j))
            case default
                p0(j) = 0.0_dp
                if (mea%estimated('t0')) p0(j) = rel%level
                if (prob%rate .and. mea%estimated('t0') .and. .not. rel%held) p0(j) = 0.0_dp
                if (prob%rates) p0(j) = 0.0_dp
                if (prob%point) p0(j) = sum(rec%vs(1:n))/n
                h(j) = H_REL*vscale
                if (prob%point) h(j) = H_REL*max(maxval(abs(rec%vs)), tiny(1.0_dp))
            end select
            prob%xs(j) = h(j)/H_REL
        end do
    end subroutine fit_problem

    !> The way the model's tracked point moves first (quantity 'point'): +1 when the
    !! record's coordinate (vcol) falls from a release at +amplitude, as theta4 does, else
    !! -1 (the model over a quarter of the record's period tp, s); +1 when it cannot tell.
    !! The release's way is then find_release's sign times this.
    real(dp) function point_way(prob, tp) result(way)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: tp
        type(start_t) :: st
        type(status_t) :: stat
        real(dp) :: v(4)
        way = 1.0_dp
        if (.not. (tp > 0.0_dp)) return
        st = prob%st
        st%amplitude = abs(st%amplitude)
        call record_model(prob%rg, st, prob%acc, [0.0_dp, 0.25_dp*tp], 0.0_dp, .false., v, &
                          stat, point=prob%q, view=prob%view)
        if (stat%code /= 0) return
        if (v(2*prob%vcol) > v(2*prob%vcol - 1)) way = -1.0_dp
    end function point_way

    !> A record of the instrument's rates that starts at its release (find_release saw no
    !! held stretch): when the vertical rate's first sample is within a tenth of the largest
    !! excursion of its mean, the record's start is the first turning point (W = 0 there),
    !! not the next crossing half a period on: the release's time, its way (the first
    !! swing's: +1 when W rises first, theta4 falling from +A) and the amplitude (the first
    !! half period's peak over 2 pi / T) from there.
    subroutine rates_from_rest(rec, rl)
        type(record_t), intent(in) :: rec       !! its values: the vertical rate
        type(record_start_t), intent(inout) :: rl
        real(dp) :: centre, band, tp
        integer :: n, i, ispan
        n = size(rec%v)
        if (n < 3) return
        centre = sum(rec%v)/n
        band = 0.1_dp*maxval(abs(rec%v - centre))
        if (.not. (abs(rec%v(1) - centre) <= band) .or. .not. (band > 0.0_dp)) return
        do i = 2, n
            if (abs(rec%v(i) - centre) > band) exit
        end do
        if (i > n) return
        rl%ifirst = 1
        rl%t0 = rec%t(1)
        rl%sign = merge(1.0_dp, -1.0_dp, rec%v(i) > centre)
        tp = rl%period
        ispan = 3
        if (tp > 0.0_dp) ispan = max(3, nint(0.5_dp*tp/((rec%t(n) - rec%t(1))/(n - 1))))
        if (tp > 0.0_dp) rl%amplitude = max(1.0e-3_dp, min(179.0_dp, &
            maxval(abs(rec%v(1:min(n, ispan)) - centre))*tp/(2.0_dp*pi)/deg))
    end subroutine rates_from_rest

    !> Fit the record by the estimator (Levenberg-Marquardt) on growing windows, each from
    !! the last estimate and with its last damping lambda (a window in the basin of the last
    !! takes Gauss-Newton steps at once), then the whole record, with the loss asked
    !! (LOSS_HUBER: then refitted with Huber's weights, res%robust their roots).  The first
    !! window is about two mean periods of the record; each next one as long as the last
    !! window's estimate predicts the model well enough to stay in the fit's basin there
    !! (window_growth), and at least twice as long.  res: the last fit (whole record);
    !! iterations summed over windows.
    subroutine fit_windows(prob, p0, h, res, stat, loss)
        type(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p0(:), h(:)
        type(lsq_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: loss   !! LOSS_SQUARES (the default) or LOSS_HUBER
        type(lsq_options_t) :: opts, defaults
        type(lsq_result_t) :: part
        real(dp) :: tp, span, win, tstart, lambda
        real(dp), allocatable :: p(:)
        integer :: n, iters, evals
        n = size(prob%rec%t)
        tp = mean_period(prob%rec, prob%ifirst)
        tstart = prob%rec%t(prob%ifirst)
        span = prob%rec%t(n) - tstart
        p = p0
        iters = 0
        evals = 0
        opts = lsq_options_t()
        opts%h = h
        opts%names = estimated_names(prob)
        lambda = opts%lambda0
        win = 2.0_dp*tp
        if (.not. (tp > 0.0_dp)) win = 2.0_dp*span
        ! a held stretch before the release: the window starts after it
        if (prob%np > 0) then
            if (any(prob%which(1:prob%np) == P_T0)) &
                win = win + max(0.0_dp, p0(findloc(prob%which(1:prob%np), P_T0, 1)) - tstart)
        end if
        do
            prob%nuse = window_end(win)
            if (prob%nuse >= n) exit
            opts%xtol = 1.0e-6_dp
            opts%gtol = 1.0_dp
            opts%lambda0 = lambda
            call estimate(prob, p, opts, part, stat)
            lambda = part%lambda
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
            win = win*window_growth(prob, part, tp)
        end do
        prob%nuse = n
        opts%xtol = defaults%xtol
        opts%gtol = defaults%gtol
        opts%lambda0 = lambda
        opts%loss = LOSS_SQUARES
        if (present(loss)) opts%loss = loss
        call estimate(prob, p, opts, res, stat)
        res%iterations = res%iterations + iters
        res%evaluations = res%evaluations + evals
    contains
        !> The last sample of a window of w seconds (at least 2 np + 1 samples).
        integer function window_end(w)
            real(dp), intent(in) :: w
            window_end = n
            if (w < span) window_end = max(count(prob%rec%t <= tstart + w), &
                                           prob%ifirst + 2*prob%np + 1)
        end function window_end
    end subroutine fit_windows
    !> Fit the record (fit_windows).  A fit of the release's tilt or sway or of the body's
    !! other moments or its mass centre (I2, I3, cg_depth) goes in stages: the parameters
    !! but I2, I3, cg_depth on the first two mean periods (where the errors of their start
    !! values have not yet turned the swings' phases; the tilt and sway found there from
    !! their start values, 0 as a rule, at which I2, I3 and cg_depth have no effect), then
    !! all but I2 on growing windows (with I3 or cg_depth), then all on the whole record.
    !! What the record separates is checked (check_separable, record_determines) before
    !! the last stage, or at the start values when neither tilt nor sway is estimated (then
    !! they are the release's): a parameter the record does not depend on, or two it cannot
    !! tell apart, is refused (ERR_DECK naming them).
    subroutine fit_record(prob, p0, h, res, stat, loss)
        type(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p0(:), h(:)
        type(lsq_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: loss   !! LOSS_SQUARES (the default) or LOSS_HUBER
        type(record_fit_t) :: sub
        type(lsq_result_t) :: part
        type(lsq_options_t) :: opts
        real(dp), allocatable :: p(:)
        logical :: later(prob%np), new_kind
        real(dp) :: tp
        integer :: j, iters, evals, stage
        integer, allocatable :: keep(:)
        new_kind = any([(any(prob%which(j) == [P_I2, P_I3, P_CG, P_TILT, P_SWAY]), &
                         j=1, prob%np)])
        if (.not. new_kind) then
            call fit_windows(prob, p0, h, res, stat, loss)
            return
        end if
        p = p0
        iters = 0
        evals = 0
        if (.not. any([(any(prob%which(j) == [P_TILT, P_SWAY]), j=1, prob%np)])) then
            ! the start values are the release's: what the record separates, at once
            prob%nuse = size(prob%rec%t)
            call check_separable(prob, p, stat)
            if (stat%code /= 0) return
        end if
        ! the stages: without I2, I3, cg_depth on the first two periods (where their start
        ! values' errors have not yet turned the swing's phases), then without I2 (the
        ! moment about the axis across CD, which the swing about CD and the sway along n1
        ! show least) on growing windows, then all on the whole record
        do stage = 1, 2
            if (stage == 1) then
                later = [(any(prob%which(j) == [P_I2, P_I3, P_CG]), j=1, prob%np)]
            else
                later = [(prob%which(j) == P_I2, j=1, prob%np)]
            end if
            if (.not. any(later) .or. all(later)) cycle
            if (stage == 2 .and. .not. any([(any(prob%which(j) == [P_I3, P_CG]), &
                                              j=1, prob%np)])) cycle
            keep = pack([(j, j=1, prob%np)], .not. later)
            sub = prob
            sub%np = size(keep)
            sub%which = 0
            sub%which(1:sub%np) = prob%which(keep)
            sub%xs = 1.0_dp
            sub%xs(1:sub%np) = prob%xs(keep)
            if (stage == 1) then
                tp = mean_period(sub%rec, sub%ifirst)
                if (.not. (tp > 0.0_dp)) tp = sub%rec%t(size(sub%rec%t)) - sub%rec%t(1)
                sub%nuse = max(count(sub%rec%t <= sub%rec%t(sub%ifirst) + 2.0_dp*tp), &
                               sub%ifirst + 2*sub%np + 1)
                sub%nuse = min(sub%nuse, size(sub%rec%t))
                opts%h = h(keep)
                opts%names = estimated_names(sub)
                call estimate(sub, p(keep), opts, part, stat)
            else
                call fit_windows(sub, p(keep), h(keep), part, stat)
            end if
            if (stat%code /= 0) then
                res = part
                return
            end if
            p(keep) = part%p
            iters = iters + part%iterations
            evals = evals + part%evaluations
        end do
        prob%nuse = size(prob%rec%t)
        call check_separable(prob, p, stat)
        if (stat%code /= 0) return
        opts%h = h
        opts%names = estimated_names(prob)
        opts%loss = LOSS_SQUARES
        if (present(loss)) opts%loss = loss
        call estimate(prob, p, opts, res, stat)
        res%iterations = res%iterations + iters
        res%evaluations = res%evaluations + evals
    end subroutine fit_record

    !> What a record determines of the parameters estimated, from the Jacobian J of its
    !! residuals (columns scaled to unit norm): the condition number, the largest
    !! off-diagonal element of the parameters' correlation matrix and its pair, and a
    !! parameter whose column is nil against the others' (the record does not depend on
    !! it; flat).  xs: each parameter's size (a column's effect is |J_j| xs_j).
    subroutine record_determines(jac, xs, d)
        real(dp), intent(in) :: jac(:, :), xs(:)
        type(determines_t), intent(out) :: d
        real(dp) :: cn(size(jac, 2)), js(size(jac, 1), size(jac, 2)), sv(size(jac, 2))
        real(dp) :: vt(size(jac, 2), size(jac, 2)), cov(size(jac, 2), size(jac, 2)), c
        type(status_t) :: st
        integer :: n, i, j
        n = size(jac, 2)
        d%np = n
        d%cond = 1.0_dp
        d%corr_max = 0.0_dp
        if (n == 0) return
        do j = 1, n
            cn(j) = norm2(jac(:, j))
        end do
        do j = 1, n
            if (.not. (cn(j)*xs(j) > FLAT_REL*maxval(cn*xs))) then
                d%flat = j
                d%cond = huge(1.0_dp)
                return
            end if
            js(:, j) = jac(:, j)/cn(j)
        end do
        if (n < 2) return
        call la_svd(js, sv, vt, st)
        if (st%code /= 0 .or. .not. (sv(n) > 0.0_dp)) then
            d%cond = huge(1.0_dp)
            d%corr_max = 1.0_dp
            d%pair = [1, 2]
            return
        end if
        d%cond = sv(1)/sv(n)
        do j = 1, n
            do i = 1, n
                cov(i, j) = sum(vt(:, i)*vt(:, j)/sv**2)
            end do
        end do
        do j = 2, n
            do i = 1, j - 1
                c = abs(cov(i, j))/sqrt(cov(i, i)*cov(j, j))
                if (c > d%corr_max) then
                    d%corr_max = c
                    d%pair = [i, j]
                end if
            end do
        end do
    end subroutine record_determines

    !> The check of what the record separates before the fit of all the parameters, at p:
    !! refused (ERR_DECK, one line naming the parameter or the pair) when the record does
    !! not depend on one (record_determines' flat), or when the correlation of two exceeds
    !! CORR_REFUSE or the condition number COND_REFUSE.
    subroutine check_separable(prob, p, stat)
        type(record_fit_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: r(:), jac(:, :)
        character(len=16) :: names(prob%np)
        type(determines_t) :: d
        type(status_t) :: st
        allocate (r(prob%nres()), jac(prob%nres(), prob%np))
        stat%code = 0
        names = estimated_names(prob)
        if (prob%has_jacobian()) then
            call record_residual_jacobian(prob, p, r, jac, st)
        else
            call prob%residual(p, r, st)
            if (st%code == 0) call lsq_jacobian(prob, p, r, H_REL*prob%xs(1:prob%np), jac, st)
        end if
        if (st%code /= 0) return               ! the fit says what fails
        call record_determines(jac, prob%xs(1:prob%np), d)
        if (d%flat > 0) then
            call set_error(stat, ERR_DECK, '&measurement estimate = '''// &
                trim(join_names(names))//''': the record cannot give '// &
                trim(names(d%flat))//': it does not depend on it (a release without tilt '// &
                'or sway shows no swing about the horizontal axes); allowed: estimate '// &
                'without '//trim(names(d%flat))//', or a record whose release tilts or sways '// &
                '(quantity = ''rates'', tilt and sway estimated)')
        else if (d%corr_max > CORR_REFUSE .or. d%cond > COND_REFUSE) then
            call set_error(stat, ERR_DECK, '&measurement estimate = '''// &
                trim(join_names(names))//''': the record cannot separate '// &
                trim(names(d%pair(1)))//' and '//trim(names(d%pair(2)))//' (correlation '// &
                sci(d%corr_max, 6)//', condition number '//sci(d%cond, 2)//'); allowed: '// &
                'estimate one of them, or a longer record or a release that moves both')
        end if
    contains
        pure function join_names(nm) result(s)
            character(len=*), intent(in) :: nm(:)
            character(len=:), allocatable :: s
            integer :: k
            s = ''
            do k = 1, size(nm)
                s = s//trim(nm(k))
                if (k < size(nm)) s = s//' '
            end do
        end function join_names
    end subroutine check_separable


    !> How much longer than the window just fitted (samples ifirst .. nuse, fit `part`) the
    !! next may be.  The estimate's covariance C = s^2 (J^T J)^-1 gives the model's standard
    !! uncertainty at each sample, sigma_i = sqrt(g_i C g_i) (g_i the model's gradient in
    !! the parameters); over the window's last period its largest, sigma_w, is compared
    !! with the swing's half range A there.  An error of the period or of the decay makes
    !! the model's error grow as t or, through the amplitude's effect on the period, as t^2:
    !! taken as (t / L)^2 from the window's length L, the next window ends where
    !! WINDOW_SIGMAS sigma reach WINDOW_PHASE A (a phase error of 0.2 rad at five standard
    !! uncertainties, well inside the basin of the fit).  At least 2 (the windows of before,
    !! also when C cannot be had).
    real(dp) function window_growth(prob, part, tp) result(g)
        type(record_fit_t), intent(in) :: prob
        type(lsq_result_t), intent(in) :: part  !! the window's fit (p, r, jac)
        real(dp), intent(in) :: tp              !! the record's mean period (s)
        real(dp), parameter :: WINDOW_SIGMAS = 5.0_dp, WINDOW_PHASE = 0.2_dp, GROWTH_MAX = 1.0e6_dp
        real(dp), allocatable :: cov(:, :)
        real(dp) :: s2, sig, sigw, vmin, vmax, tend, gi(prob%np), vi
        type(status_t) :: st
        integer :: m, i, k, o, ms
        g = 2.0_dp
        m = size(part%r)
        if (m <= prob%np .or. prob%np == 0 .or. .not. allocated(part%jac)) return
        s2 = part%cost/(m - prob%np)
        call lsq_covariance(part%jac, s2, cov, st)
        if (st%code /= 0) return
        tend = prob%rec%t(prob%nuse)
        sigw = 0.0_dp
        vmin = huge(1.0_dp)
        vmax = -huge(1.0_dp)
        ms = prob%nuse - prob%ifirst + 1
        do o = 1, prob%nout
            do i = prob%ifirst, prob%nuse
                if (prob%rec%t(i) < tend - tp) cycle
                k = (o - 1)*ms + i - prob%ifirst + 1
                gi = part%jac(k, :)/(prob%w(i)*prob%hw(i))
                sig = sqrt(max(0.0_dp, dot_product(gi, matmul(cov, gi))))
                sigw = max(sigw, sig)
                vi = prob%rec%v(i)
                if (prob%rates) vi = prob%rec%vs((o - 1)*size(prob%rec%t) + i)
                vmin = min(vmin, vi)
                vmax = max(vmax, vi)
            end do
        end do
        if (.not. (vmax > vmin)) return
        ! an exact fit (sigma_w 0 or at roundoff): the next window is the whole record
        g = GROWTH_MAX
        if (sigw > 1.0e-12_dp*(vmax - vmin)) g = min(GROWTH_MAX, max(2.0_dp, &
            sqrt(WINDOW_PHASE*0.5_dp*(vmax - vmin)/(WINDOW_SIGMAS*sigw))))
    end function window_growth

    !> The integrated correlation time of a sequence of residuals, in samples:
    !! 1 + 2 sum_k rho_k over the lags k = 1, 2, ... while the autocorrelation rho_k stays
    !! positive (Geyer's initial positive sequence), at most n/4 lags; 1 for white residuals.
    !! n / tau is the effective number of independent samples, tau the factor of the
    !! covariance a fit that takes them for independent underestimates.
    pure real(dp) function correlation_time(r) result(tau)
        real(dp), intent(in) :: r(:)
        real(dp) :: m, c0, ck, x(size(r))
        integer :: n, k
        n = size(r)
        tau = 1.0_dp
        if (n < 8) return
        m = sum(r)/n
        x = r - m
        c0 = sum(x*x)/n
        if (.not. (c0 > 0.0_dp)) return
        do k = 1, n/4
            ck = sum(x(1:n - k)*x(1 + k:n))/n
            if (ck/c0 <= 0.0_dp) exit
            tau = tau + 2.0_dp*ck/c0
        end do
    end function correlation_time

    !> A fit that gave no estimate (ERR_NUMERIC, exit 3): the message gets the residual in
    !! the record's unit (rad, rad/s; a track's in m, and in px by record_scale) and what to
    !! check; for a track first record_scale, with the swing in m that it gives.
    subroutine explain_fit_failure(stat, prob, fit)
        type(status_t), intent(inout) :: stat
        type(record_fit_t), intent(in) :: prob
        type(lsq_result_t), intent(in) :: fit
        character(len=:), allocatable :: what, units
        real(dp) :: rms, sc
        integer :: i0, i1
        what = stat%msg
        if (index(what, 'identify: ') == 1) what = what(11:)
        rms = 0.0_dp
        i0 = prob%ifirst
        i1 = i0 - 1
        if (allocated(fit%r)) i1 = min(prob%nuse, prob%ifirst + size(fit%r) - 1)
        if (i1 >= i0) rms = sqrt(sum((fit%r(1:i1 - i0 + 1)/ &
            (prob%w(i0:i1)*prob%hw(i0:i1)))**2)/max(1, i1 - i0 + 1))
        units = trim(merge(' rad  ', ' rad/s', .not. prob%rate))//'); check the record''s'// &
            ' units (t in s; record_units)'
        if (prob%point) then
            ! a track: the residual in its unit times record_scale (m a unit), the swing in m
            sc = prob%scale(1)
            units = ' m'
            if (sc /= 1.0_dp) units = units//', '//sci(rms)//' px'
            units = units//'); check record_scale = '//rshort(sc)//' m a unit of the track, '// &
                'which makes its swing '//sci(sc*(maxval(prob%rec%v) - minval(prob%rec%v)), 3)// &
                ' m (allowed: record_scale in m/px, '//rshort(sc)//' mm/px is '// &
                rshort(1.0e-3_dp*sc)//', or the columns named in m, cm or mm and record_scale '// &
                'left out; record_units is not used for a track), t in s'
            rms = sc*rms
        end if
        stat%code = ERR_NUMERIC
        stat%msg = 'identify: '//what//' (residual rms '//sci(rms)//units// &
            ', the start (&start amplitude; add t0 to '// &
            'estimate to find the release), the rig''s lengths and the start value of I1 '// &
            '(&body inertia(1)), or estimate fewer parameters'
    end subroutine explain_fit_failure

    !> dp/dx = -(J^T J)^-1 J^T dr/dx at the estimate for the input x (dr/dx by central
    !! differences with a relative step H_REL, or H_REL b' for an input of value 0; the
    !! weights are in J and r).
    subroutine input_sensitivity(prob, p, jac, x, dpdx, stat)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: p(:), jac(:, :)
        type(input_t), intent(in) :: x          !! the input (name, value)
        real(dp), intent(out) :: dpdx(:)
        type(status_t), intent(out) :: stat
        type(record_fit_t) :: pp, pm
        real(dp) :: hx, rp(size(jac, 1)), rm(size(jac, 1))
        hx = H_REL*abs(x%value)
        if (.not. (hx > 0.0_dp)) hx = H_REL*prob%rg%b_prime
        if (trim(x%name) == 'lambda') hx = H_REL
        pp = prob
        pm = prob
        call set_input(pp%rg, pp%st, x%name, x%value + hx)
        call set_input(pm%rg, pm%st, x%name, x%value - hx)
        call pp%residual(p, rp, stat)
        if (stat%code /= 0) return
        call pm%residual(p, rm, stat)
        if (stat%code /= 0) return
        call la_lstsq(jac, (rp - rm)/(2.0_dp*hx), dpdx, stat)
        dpdx = -dpdx
    end subroutine input_sensitivity

    !> dp/dx = -(J^T J)^-1 J^T dr/dx at the estimate for every input x with u > 0 at once,
    !! dr/dx from the forward sensitivities of one run (record_model_sens), or of the fit's
    !! last run when it carried them at the estimate (model_values); dpdx(:, j) = 0 for an
    !! input without u.  With &integration sensitivities = 'differences', central
    !! differences of whole runs, two per input (input_sensitivity).
    subroutine input_sensitivities(prob, p, jac, x, dpdx, runs, stat)
        type(record_fit_t), intent(in) :: prob
        real(dp), intent(in) :: p(:), jac(:, :)
        type(input_t), intent(in) :: x(:)       !! the inputs (name, value, u)
        real(dp), intent(out) :: dpdx(:, :)     !! (size(p), size(x))
        integer, intent(out) :: runs            !! model runs made
        type(status_t), intent(out) :: stat
        type(rig_t) :: rg
        type(start_t) :: st
        real(dp) :: t0, bias(3)
        real(dp), allocatable :: vals(:), dv(:, :), xs(:), w(:)
        character(len=16), allocatable :: names(:)
        integer, allocatable :: idx(:)
        integer :: i0, i1, j, c, m
        logical :: ok
        dpdx = 0.0_dp
        runs = 0
        stat%code = 0
        if (prob%acc%sensitivities /= SENS_FORWARD) then
            do j = 1, size(x)
                if (.not. (x(j)%u > 0.0_dp)) cycle
                call input_sensitivity(prob, p, jac, x(j), dpdx(:, j), stat)
                runs = runs + 2
                if (stat%code /= 0) then
                    stat%msg = 'sensitivity to '//trim(x(j)%name)//': '//stat%msg
                    return
                end if
            end do
            return
        end if
        allocate (names(0), xs(0), idx(0))
        call budget_columns(prob, x, names, xs)
        do j = 1, size(x)
            if (x(j)%u > 0.0_dp) idx = [idx, j]
        end do
        if (size(names) == 0) return
        call apply_parameters(prob, p, rg, st, t0, bias)
        i0 = prob%ifirst
        i1 = prob%nuse
        m = i1 - i0 + 1
        call prob%runs%carried(run_point_t(rg, st, t0), m, x, size(names), dv, ok)
        if (.not. ok) then
            allocate (vals(prob%nout*m), dv(prob%nout*m, size(names)))
            if (prob%rates) then
                call record_model_sens(rg, st, prob%acc, prob%rec%t(i0:i1), t0, prob%rate, &
                                       names, xs, vals, dv, stat, prob%axes)
            else
                call record_model_sens(rg, st, prob%acc, prob%rec%t(i0:i1), t0, prob%rate, &
                                       names, xs, vals, dv, stat)
            end if
            runs = 1
            if (stat%code /= 0) then
                stat%msg = 'sensitivities to the inputs: '//stat%msg
                return
            end if
        end if
        if (prob%turn /= 1.0_dp) call turn_columns(prob, names, dv)
        w = stacked_weights(prob)
        do c = 1, size(names)
            call la_lstsq(jac, prob%sign*dv(:, c)*w, dpdx(:, idx(c)), stat)
            if (stat%code /= 0) return
            dpdx(:, idx(c)) = -dpdx(:, idx(c))
        end do
    end subroutine input_sensitivities

    !> The size of an input for its difference step: |value|, b' for an input of value 0,
    !! 1 rad for lambda (as input_sensitivity's steps, over H_REL).
    pure real(dp) function input_size(prob, x) result(xs)
        type(record_fit_t), intent(in) :: prob
        type(input_t), intent(in) :: x
        xs = abs(x%value)
        if (.not. (xs > 0.0_dp)) xs = prob%rg%b_prime
        if (trim(x%name) == 'lambda') xs = 1.0_dp
    end function input_size

    !> The samples of a record fit's Monte Carlo from the deck, its record, its inputs and
    !! the payload of the record's Monte Carlo (the task rank 0 runs and the other ranks
    !! build).
    subroutine record_mc_task(rg, st, acc, mea, rec, x, payload, task)
        type(rig_t), intent(in) :: rg           !! the deck's rig
        type(start_t), intent(in) :: st         !! its start
        type(accuracy_t), intent(in) :: acc     !! its runs' accuracy
        type(measurement_group_t), intent(in) :: mea    !! (seed, quantity, estimate)
        type(record_t), intent(in) :: rec
        type(input_t), intent(in) :: x(:)       !! the inputs drawn
        !> crc (2), sigma, np, phat, u_p, jac, the robust weights' roots (1 .. n) and the
        !! parameters' sensitivities to the inputs (np x size(x))
        real(dp), intent(in) :: payload(:)
        type(record_mc_task_t), intent(out) :: task
        real(dp), allocatable :: p0(:), h(:)
        integer :: np, m, k
        call fit_problem(rg, st, acc, mea, rec, task%prob, p0, h)
        task%x = x
        m = task%prob%nres()
        task%sigma = payload(3)
        np = nint(payload(4))
        task%phat = payload(5:4 + np)
        task%u_p = payload(5 + np:4 + 2*np)
        task%jac = reshape(payload(5 + 2*np:4 + 2*np + m*np), [m, np])
        k = 4 + 2*np + m*np
        if (size(payload) >= k + size(task%prob%hw)) task%prob%hw = payload(k + 1:k + &
                                                                           size(task%prob%hw))
        k = k + size(task%prob%hw)
        if (size(payload) >= k + np*size(x)) task%dpdx = reshape(payload(k + 1:k + np*size(x)), &
                                                                 [np, size(x)])
        task%nest = np
    end subroutine record_mc_task

    !> Monte Carlo sample k of a record fit: inputs and measured values drawn from stream k
    !! of the seed, then the refit by Gauss-Newton with the estimate's Jacobian, from the
    !! sample's first-order estimate (forward sensitivities: the estimate moved by the
    !! parameters' sensitivities to the inputs drawn and by J^+ of the values' noise) or from
    !! the estimate itself, until the error left is below MC_TOL u of each parameter (the
    !! last step, times the iteration's contraction); est: the sample's parameters (I1 first).
    !! A failed refit: ERR_NUMERIC naming the sample.
    subroutine record_mc_point(self, k, est, stat)
        class(record_mc_task_t), intent(in) :: self
        integer, intent(in) :: k                !! sample number
        real(dp), intent(out) :: est(:)         !! the sample's parameters
        type(status_t), intent(out) :: stat
        type(record_fit_t) :: q
        type(rng_t) :: g
        type(lsq_result_t) :: fit
        type(lsq_options_t) :: opts
        real(dp) :: p(size(self%phat)), dp_(size(self%phat)), r(size(self%jac, 1))
        real(dp) :: h(size(self%phat)), dx(size(self%x)), d, dprev, rate
        integer :: j, it, o
        logical :: done
        est = 0.0_dp
        g = rng_stream(self%prob%seed, k)
        q = self%prob
        dx = 0.0_dp
        do j = 1, size(self%x)
            if (self%x(j)%u > 0.0_dp) then
                dx(j) = self%x(j)%u*rng_normal(g)
                call set_input(q%rg, q%st, self%x(j)%name, self%x(j)%value + dx(j))
            end if
        end do
        if (q%rates) then
            do o = 1, 3
                do j = 1, size(q%rec%t)
                    q%rec%vs((o - 1)*size(q%rec%t) + j) = self%prob%rec%vs((o - 1)* &
                        size(q%rec%t) + j) + self%sigma*rng_normal(g)/ &
                        self%prob%w(j)
                end do
            end do
        end if
        do j = 1, size(q%rec%v)
            if (q%rates) exit
            if (self%prob%rec%has_u) then
                q%rec%v(j) = self%prob%rec%v(j) + self%prob%rec%u(j)*rng_normal(g)
            else
                q%rec%v(j) = self%prob%rec%v(j) + self%sigma*rng_normal(g)
            end if
        end do
        ! Gauss-Newton with the estimate's Jacobian
        p = self%phat
        if (q%has_jacobian() .and. allocated(self%dpdx)) then
            ! the first-order estimate: the inputs' part, and the values' noise through J^+
            call la_lstsq(self%jac, (stacked_values(q) - stacked_values(self%prob))* &
                          stacked_weights(q), dp_, stat)
            if (stat%code == 0) p = p + dp_ + matmul(self%dpdx, dx)
        end if
        ! each step measured against its tolerance, MC_TOL u of its parameter; the iteration
        ! contracts (the Jacobian is the estimate's, not the sample's): the error left after
        ! a step of size d is below rate/(1 - rate) d, rate measured from the last two steps
        ! (MC_RATE before there are two)
        done = .false.
        dprev = 0.0_dp
        do it = 1, 8
            call q%residual(p, r, stat)
            if (stat%code /= 0) exit
            call la_lstsq(self%jac, -r, dp_, stat)
            if (stat%code /= 0) exit
            p = p + dp_
            d = maxval(abs(dp_)/(MC_TOL*self%u_p + 1.0e-14_dp*abs(p) + tiny(1.0_dp)))
            rate = MC_RATE
            if (it > 1) rate = d/max(dprev, tiny(1.0_dp))
            if (d <= 1.0_dp .or. (rate < 0.5_dp .and. rate/(1.0_dp - rate)*d <= 1.0_dp)) then
                done = .true.
                exit
            end if
            dprev = d
        end do
        if (.not. done) then
            do j = 1, size(p)
                h(j) = H_REL*max(abs(self%phat(j)), self%u_p(j))
            end do
            opts%h = h
            call estimate(q, self%phat, opts, fit, stat)
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
    subroutine make_record(rg, st, acc, title, deck_path, duration, rate_hz, sigma, seed, &
                           quantity, path, stat)
        type(rig_t), intent(in) :: rg           !! the true rig (of a simulate deck)
        type(start_t), intent(in) :: st         !! its start
        type(accuracy_t), intent(in) :: acc     !! its runs' accuracy
        character(len=*), intent(in) :: title   !! the deck's &scene title
        character(len=*), intent(in) :: deck_path   !! the deck as given
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
        call record_model(rg, st, acc, t, 0.0_dp, quantity == 'rate', &
                          v, stat)
        if (stat%code /= 0) return
        g = rng_stream(seed, 0)
        do i = 0, n
            v(i) = v(i) + sigma*rng_normal(g)
        end do
        call files%open(path, u, stat)
        if (stat%code /= 0) return
        ios = 0
        write (u, '(a)', iostat=ios) '# bifilar make_record: '//trim(title)
        if (ios == 0) write (u, '(a)', iostat=ios) '# simulated from '//deck_path// &
            ' (&damping c_v = '//sci(rg%c_v, 6)//', c_q = '//sci(rg%c_q, 6)//', I1 = '// &
            sci(rg%inertia(1), 6)//'), noise sigma = '//sci(sigma, 3)//', seed '//itoa(seed)
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


    !> A record of quantity 'rates': its value v set to the rate about the vertical the
    !! instrument's three rates give, W = -omega . b_1 (b_1 points down at rest), for the
    !! release, the period and the checks of a one-value record.
    pure subroutine vertical_of_rates(rec, axes)
        type(record_t), intent(inout) :: rec
        real(dp), intent(in) :: axes(3, 3)      !! the instrument's axes in b_i (rows)
        integer :: n
        if (.not. allocated(rec%vs)) return
        n = size(rec%t)
        rec%v = -(axes(1, 1)*rec%vs(1:n) + axes(2, 1)*rec%vs(n + 1:2*n) + &
                  axes(3, 1)*rec%vs(2*n + 1:3*n))
    end subroutine vertical_of_rates

end module record_fit
