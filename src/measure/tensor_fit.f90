!> The whole inertia tensor from the periods of several hangs (analysis tensor): the
!! projection solution, the exact fit, its uncertainty, the amplitude limit of a hang, the
!! plan of hangs, and the Monte Carlo task.
!!
!! * The problem: the six entries x = (J_xx, J_yy, J_zz, J_xy, J_xz, J_yz) of the tensor
!!   about the mass centre in the body frame; each row of the table of hangs (module
!!   measurement_read) a measured period T_i of hang h(i) at amplitude A_i; the model period
!!   T(x; hang, A) of module hang_model (the torsion mode of the linearised full model at
!!   A = 0, the full model's time from release to the next maximum of theta_4 at A > 0).
!!   Rows of one hang at one amplitude share one model period (a case).
!! * Directions: the moment about the vertical of a hang is u . J u = a(u) . x
!!   (moment_direction).  Six directions, no two parallel, whose design matrix (rows a(u)
!!   of the distinct unit up directions) has condition <= COND_MAX determine x; fewer or a
!!   worse condition are refused (check_directions), naming the face, edge or corner
!!   directions of the body frame whose hangs would make it determined.
!! * The projection solution (projection): the tool in use: the linear formula per row,
!!   u . J u = m g b b' T^2 / (16 pi^2 l) (l the mean cable length), then least squares of
!!   a(u) . x on those moments (LAPACK dgels).
!! * The fit (fit_tensor): generalised least squares, min r^T V^-1 r, r = T(x) - T_meas,
!!   by Gauss-Newton from the projection solution (the estimator, module estimator; the
!!   Jacobian by forward differences of the model; a step that fails or raises the sum is
!!   halved), whitened by the Cholesky
!!   factor of V (LAPACK dpotrf, dtrtrs) and solved by dgels.  V holds what scatters the
!!   rows independently of the tensor: each row's timing (u_period over cycles), its
!!   amplitude (u_amplitude times dT/dA), the definition of its period (u_def, below), and
!!   per hang, shared by its rows, how the body was set (three small rotations about
!!   ntilde_1, ntilde_2, ntilde_3, each u_direction) and the hang's own rig columns.  V is
!!   evaluated at the start and again at the first solution, then the fit is repeated from
!!   there.  A row without any stated uncertainty counts 1e-9 of its period; a table
!!   without any (no u_period, u_amplitude, u_direction) is fitted with equal weights and
!!   the timing's u taken from the scatter, s^2 = sum r^2/(n - 6).
!! * First-order uncertainty (GUM): every input x_k moves the estimate by
!!   S_k = -(A_w^T A_w)^-1 A_w^T L^-1 dr/dx_k (A_w = L^-1 A, V = L L^T); the covariance is
!!   C = sum_k S_k S_k^T u_k^2 over the timing, amplitude and definition of every row, the
!!   direction and own rig of every hang (together the fit's covariance (A_w^T A_w)^-1) and
!!   the inputs common to every hang: mass (dT/dm = -(1/m) sum x_p dT/dx_p, exactly: the
!!   model sees J/m), g (dT/dg = -T/(2 g)), and the deck's l, l_prime, b, b_prime (central
!!   differences of the model).  The principal moments (LAPACK dsyev) have
!!   u^2 = a(v_k)^T C a(v_k); axis k turns toward axis j by (v_j^T dJ v_k)/(I_k - I_j), and
!!   its u in degrees is the root sum of the two.  Coverage: Welch-Satterthwaite over the
!!   inputs (a timing u from the scatter has n - 6 degrees of freedom, the others are Type B:
!!   infinite), k from Student's t (module stats).
!! * The self-check: with the rows' u stated (not from the scatter) and p < 0.05, the fit is
!!   inconsistent and every per-hang source (timing, amplitude, definition, direction, own
!!   rig: together the fit's covariance) is inflated by the Birge ratio (chi^2/dof)^(1/2),
!!   so that no u is below what the residuals imply; those rows then carry the n - 6
!!   degrees of freedom of that ratio into Welch-Satterthwaite.
!! * The chi-square r_w^T r_w of the rows against the fit with n - 6 degrees of freedom;
!!   per hang, the vertical moment its rows measure, I_v = u . J u + delta with delta the
!!   generalised least-squares shift of u . J u alone that its rows ask for, its u from the
!!   hang's own V block, and its normalised residual delta/u.
!! * The amplitude limit (amplitude_limits): a hang whose vertical is not a principal axis
!!   does not twist purely, and at finite amplitude the quadratic terms of the equations
!!   feed the other modes: the time to the next maximum of theta_4 then depends on which
!!   cycle is timed.  The drift is the largest change of the interval between successive
!!   maxima over the first DRIFT_CYCLES cycles, relative to the first (hang_model's
!!   maxima_drift); a hang's period at amplitude A is defined well enough while the drift is
!!   at most DRIFT_MAX.  Larger amplitudes are refused; smaller ones carry the drift as a
!!   Type B uncertainty of the period's definition, u_def = drift T/3^(1/2) (the period
!!   timed over any of those cycles lies within drift T of the first).  Each hang's limit is
!!   found by doubling the amplitude from 1 degree and bisecting in log A.
!! * A fixture (&tensor fixture_*) and the mass centre fitted (estimate = 'tensor cg'): the
!!   model of every case is that of what hangs (hang_model's loaded_hang, problem_rig); the
!!   fixture's mass, mass centre and inertia are common inputs of the budget (differences;
!!   the inertia exactly through dT/dx), and the mass's sensitivity is by differences.  With
!!   the mass centre the parameters are nine (x and its shift dcg) and each hang with an
!!   attitude adds a residual, the sine of the angle between the measured gravity and the
!!   plane of C, D and the mass centre (attitude_residual), in the hang's block of V with
!!   u_attitude and the hang's rotations.
!! * The plan (plan_hangs): n hangs among the 13 face, edge and corner directions of the
!!   body frame (u and -u one; along: the first of the 26 normal to up), each at small
!!   amplitude on the deck's rig, that minimise the trace of C under the deck's
!!   uncertainties (the periods' sensitivities of the linearised model at the given
!!   tensor), none planned twice before each is planned once: a well-conditioned start
!!   (the three faces and three edges), greedy additions, then exchanges until none lowers
!!   the trace; or n hangs added to the table's (each with its own timing u).
!! * Monte Carlo (GUM Supplement 1): sample k draws from stream k of the seed, in this
!!   order, mass, g, l, l_prime, b, b_prime; per hang the three rotations and its four rig
!!   inputs; per row its timing, amplitude (normal) and definition (uniform within
!!   +-3^(1/2) u_def); then refits by Gauss-Newton with the estimate's Jacobian (each step
!!   one model period per case) until each step is below 1e-3 of the entry's first-order u,
!!   and gives x, the principal moments and the turns of the axes toward the others.  With
!!   the mass centre fitted the fixture is drawn next, then each measured attitude's reading
!!   (its residual off by u_attitude); the refit takes the nine parameters with the
!!   9 x (rows + attitudes) chord and gives dcg too.  The
!!   samples are a sweep (module monte_carlo); the task is built from the deck and the
!!   payload (tensor_mc_payload, tensor_mc_task).
!!
!! Units are the deck's (mass x length^2, s); directions in degrees in messages.  No
!! routine stops; failures come back in status_t.
module tensor_fit
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC
    use text, only: itoa, sci, fixed, rshort, rlist_short
    use rig_groups, only: suspension_group_t, body_group_t
    use measure_groups, only: tensor_group_t
    use rig, only: rig_t, accuracy_t
    use lapack_wrap, only: la_lstsq, la_svd, la_syev, la_chol, la_tri_solve
    use random, only: rng_t, rng_stream, rng_normal, rng_uniform
    use stats, only: chi2_sf, coverage_factor, welch_satterthwaite, NU_INFINITE
    use budget, only: ROW_INPUT, ROW_TIMING, ROW_AMPLITUDE, ROW_DEFINITION, ROW_DIRECTION
    use estimator, only: lsq_problem_t, lsq_options_t, lsq_result_t, estimate, DAMP_HALVING, &
        STEP_LARGEST, STEP_SCALED, FAIL_FLOOR, FAIL_ITERATIONS
    use monte_carlo, only: mc_task_t
    use measurement, only: measurement_t, observation_t, hang_t, OBS_HANG, RIG_COLUMNS
    use hang_model, only: tensor_entries, principal_axes, hang_rig, hang_period, &
        maxima_drift, vertical_moment, moment_direction, turned_hang, fixture_t, loaded_hang, &
        plane_normal, fixture_in_body, platform_points_t
    use unused_arg, only: unused
    use vectors, only: cross
    implicit none
    private

    !> The standard uncertainties of the inputs that are not the periods' timing (deck
    !! units; amplitude in degrees, direction in rad).
    type, public :: tensor_u_t
        real(dp) :: mass = 0.0_dp, g = 0.0_dp
        real(dp) :: rig(4) = 0.0_dp             !! l, l_prime, b, b_prime
        real(dp) :: amplitude = 0.0_dp          !! degrees
        real(dp) :: direction = 0.0_dp          !! rad, each of the three rotations
        real(dp) :: fix_mass = 0.0_dp, fix_cg(3) = 0.0_dp   !! the fixture's
        real(dp) :: fix_inertia(6) = 0.0_dp     !! of its entries (xx, yy, zz, xy, xz, yz)
        real(dp) :: attitude = 0.0_dp           !! rad, of a hang's measured attitude
    end type tensor_u_t

    !> What the fit needs: the body's mass, gravity, the hangs and their timings, the runs'
    !! accuracy, the uncertainties.
    type, public :: tensor_problem_t
        real(dp) :: mass = 1.0_dp, g = 1.0_dp
        type(hang_t), allocatable :: hangs(:)
        type(observation_t), allocatable :: rows(:)     !! the timings (OBS_HANG), by hang
        type(accuracy_t) :: acc
        type(tensor_u_t) :: u
        real(dp), allocatable :: u_def(:)       !! per row: the period's definition (s)
        integer, allocatable :: row_case(:)     !! per row: its case (hang and amplitude)
        integer, allocatable :: case_hang(:)    !! per case: its hang
        real(dp), allocatable :: case_amp(:)    !! per case: its amplitude (degrees)
        type(fixture_t) :: fix                  !! a fixture in every hang (mass 0: none)
        real(dp) :: origin(3) = 0.0_dp          !! where the table's mass centre lies
        real(dp) :: dcg(3) = 0.0_dp             !! the body's mass centre from the table's
        !> the model composes each hang (loaded_hang): a fixture, or the mass centre fitted
        logical :: loaded = .false.
        logical :: est_cg = .false.             !! estimate = 'tensor cg'
        integer :: np = 6                       !! parameters: 6, or 9 with the mass centre
        integer, allocatable :: att_hang(:)     !! per attitude residual: its hang
        !> a platform given point by point (the deck's &suspension; else not given)
        type(platform_points_t) :: pts
    end type tensor_problem_t

    !> One line of the budget: an input (or the inputs of a hang) and what it adds to the
    !! standard uncertainty of each entry.
    type, public :: tensor_budget_row_t
        character(len=24) :: input = ''
        real(dp) :: u = 0.0_dp                  !! the input's u (direction in degrees)
        real(dp) :: contribution(6) = 0.0_dp    !! to J_xx ... J_yz
        integer :: kind = ROW_INPUT             !! ROW_* of module budget: what the input is
    end type tensor_budget_row_t

    !> The fit and its uncertainty.
    type, public :: tensor_fit_t
        real(dp) :: x(6) = 0.0_dp               !! the entries
        real(dp) :: x_proj(6) = 0.0_dp          !! the projection solution
        real(dp) :: cov(6, 6) = 0.0_dp          !! first-order covariance of x
        real(dp) :: u_x(6) = 0.0_dp
        real(dp) :: moments(3) = 0.0_dp         !! principal moments, ascending
        real(dp) :: u_moments(3) = 0.0_dp
        real(dp) :: axes(3, 3) = 0.0_dp         !! column k: axis of moments(k)
        real(dp) :: u_axes(3) = 0.0_dp          !! degrees
        real(dp) :: nu_eff(3) = NU_INFINITE     !! effective degrees of freedom of u_moments
        real(dp) :: k95(3) = 0.0_dp             !! their coverage factors for 95 %
        real(dp) :: chi2 = 0.0_dp, p_value = 1.0_dp
        integer :: dof = 0
        !> the self-check (module header): tested (u stated, dof > 0), consistent (p >=
        !! 0.05), the Birge ratio (chi^2/dof)^(1/2), inflation (the Birge ratio when
        !! inconsistent, else 1)
        logical :: tested = .false., consistent = .true.
        real(dp) :: birge = 0.0_dp, inflation = 1.0_dp
        real(dp) :: condition = 0.0_dp          !! of the directions' design matrix
        real(dp) :: projection_difference = 0.0_dp  !! max |x_proj - x| / moments(3)
        logical :: scatter = .false.            !! timing u from the residuals' scatter
        real(dp) :: u_scatter = 0.0_dp          !! that u (s)
        integer :: iterations = 0, evaluations = 0
        real(dp), allocatable :: model_period(:)    !! per row (s)
        real(dp), allocatable :: iv_fit(:), iv(:), u_iv(:), resid(:)  !! per hang
        type(tensor_budget_row_t), allocatable :: budget(:)
        real(dp), allocatable :: chord(:, :)    !! 6 x rows: the step -chord r (Monte Carlo)
        real(dp), allocatable :: u_row(:)       !! per row: the timing's u used (s)
        !> with the mass centre fitted: the body's mass centre from the table's (body
        !! frame), its u, the joint covariance of (x, dcg) and each attitude's residual
        real(dp) :: dcg(3) = 0.0_dp, u_dcg(3) = 0.0_dp
        real(dp), allocatable :: cov_all(:, :)
        real(dp), allocatable :: att_resid(:)   !! normalised, per attitude
    end type tensor_fit_t

    !> The sensitivities a fixture or a fitted mass centre adds: per case, the period over
    !! the fixture's mass and mass centre (4); per attitude residual, over the three
    !! rotations of its hang, the body's mass and the fixture's mass and mass centre.
    type :: extra_sens_t
        real(dp), allocatable :: fix(:, :)      !! (cases, 4)
        real(dp), allocatable :: att_dir(:, :)  !! (attitudes, 3)
        real(dp), allocatable :: att_mass(:)    !! (attitudes)
        real(dp), allocatable :: att_fix(:, :)  !! (attitudes, 4)
    end type extra_sens_t

    !> The covariance of the rows of one hang, as its Cholesky factor once factored.
    type :: block_t
        integer, allocatable :: rows(:)         !! the hang's rows
        real(dp), allocatable :: l(:, :)        !! V of those rows, then L with V = L L^T
    end type block_t

    !> The tensor's fit as a least-squares problem of the estimator (gauss_newton): the
    !! rows' whitened residuals of the six entries.
    type, extends(lsq_problem_t) :: tensor_lsq_t
        type(tensor_problem_t) :: tp            !! the problem
        type(block_t), allocatable :: blocks(:) !! the rows' covariance, factored
        real(dp), allocatable :: tc(:)          !! the model's periods of the cases at x_last
        real(dp) :: x_last(9) = huge(1.0_dp)
    contains
        procedure :: residual => tensor_residual
        procedure :: nres => tensor_nres
        procedure :: jacobian => tensor_jacobian
    end type tensor_lsq_t

    !> A plan of hangs.
    type, public :: tensor_plan_t
        integer :: n = 0
        real(dp), allocatable :: up(:, :), along(:, :)  !! 3 x n, body frame
        real(dp), allocatable :: period(:)      !! predicted at small amplitude (s)
        real(dp) :: trace = 0.0_dp              !! of the covariance of x
        real(dp) :: u_x(6) = 0.0_dp             !! predicted standard uncertainties
        !> with the mass centre fitted (estimate = 'tensor cg'): its predicted u (body frame)
        real(dp) :: u_cg(3) = 0.0_dp
    end type tensor_plan_t

    !> The sensitivities of a candidate hang that fitting the mass centre adds (plan): the
    !! period over the mass centre's shift, and the attitude residual over the shift, the
    !! hang's three rotations and the body's mass.
    type :: cg_sens_t
        real(dp), allocatable :: t_cg(:, :)     !! (candidates, 3)
        logical, allocatable :: att(:)          !! the candidate's attitude is measured
        real(dp), allocatable :: r_cg(:, :), r_dir(:, :), r_mass(:)  !! (candidates, 3 | 1)
    end type cg_sens_t

    !> The samples of the Monte Carlo of a tensor fit as a sweep (built by tensor_mc_task).
    type, extends(mc_task_t), public :: tensor_mc_task_t
        type(tensor_problem_t) :: prob
        real(dp) :: x(6) = 0.0_dp               !! the estimate
        real(dp) :: axes(3, 3) = 0.0_dp         !! its principal axes
        !> 6 x rows; with the mass centre fitted 9 x (rows + attitudes)
        real(dp), allocatable :: chord(:, :)
        real(dp), allocatable :: u_row(:)       !! per row: timing u (s)
        real(dp) :: u_x(6) = 0.0_dp             !! the estimate's first-order u
        !> with the mass centre fitted: its estimated shift and that shift's first-order u
        real(dp) :: dcg(3) = 0.0_dp, u_dcg(3) = 0.0_dp
        !> per case: the amplitude part of its period and its derivatives (amplitude_parts)
        real(dp), allocatable :: parts(:, :)
        integer :: seed = 1
    contains
        procedure :: sample => tensor_mc_point
    end type tensor_mc_task_t

    public :: problem_of, check_directions, projection, fit_tensor, amplitude_limits
    public :: plan_hangs, design_trace, candidate_directions, along_for
    public :: tensor_mc_payload, tensor_mc_task, tensor_mc_sample, model_periods
    public :: distinct_directions, amplitude_parts

    !> Largest condition number of the directions' design matrix.
    real(dp), parameter, public :: COND_MAX = 1.0e8_dp
    !> The drift of theta_4's maxima up to which a period counts as defined, and the cycles
    !! watched.
    real(dp), parameter, public :: DRIFT_MAX = 1.0e-3_dp
    integer, parameter, public :: DRIFT_CYCLES = 10
    !> Estimates of a Monte Carlo sample: x (6), principal moments (3), the turns of axis k
    !! toward the two others (6); with the mass centre fitted also its shift dcg (3).
    integer, parameter, public :: MC_ESTIMATES = 18
    !> Values per case of amplitude_parts: D, dD/dx (6), dD/deps (3), dD/drig (4), dD/dA.
    integer, parameter, public :: MC_PARTS = 15

    !> The tensor Monte Carlo payload's sections (tensor_mc_payload), by their lengths: a
    !! head (seed, hangs, rows), MC_HANG_LEN per hang, MC_ROW_LEN per row, the fit
    !! (MC_FIT_LEN: origin, x, axes, u_x), its chord's first six rows (6 per row), the
    !! cases' amplitude parts (their count, then MC_PARTS per case); with the mass centre
    !! fitted a tail: MC_CG_LEN (origin, dcg, u_dcg), MC_GRAV_LEN per hang (gravity,
    !! measured), the whole chord (9 per row and attitude).
    integer, parameter :: MC_HEAD_LEN = 3, MC_HANG_LEN = 17, MC_ROW_LEN = 7, &
        MC_FIT_LEN = 24, MC_CG_LEN = 9, MC_GRAV_LEN = 4

    !> Where each section of a payload starts (the index before its first entry) and
    !! the payload's length, for nh hangs, n rows, nc cases and na measured attitudes.
    type :: mc_layout_t
        integer :: hangs = 0, rows = 0, fit = 0, chord = 0, parts = 0
        integer :: cg = 0, grav = 0, cg_chord = 0, total = 0
    end type mc_layout_t
    !> Two unit directions count as one when |u . v| exceeds 1 - PARALLEL_TOL.
    real(dp), parameter :: PARALLEL_TOL = 1.0e-9_dp
    !> A period without any stated uncertainty counts this much of itself.
    real(dp), parameter :: U_FLOOR = 1.0e-9_dp
    !> Gauss-Newton: iterations, and the step that ends them over the largest moment (at
    !! small amplitude; simulated periods: 10 rtol at least); a step up to 1000 times that
    !! ends them too when it lowers the misfit by less than 1e-10 of itself.
    integer, parameter :: MAX_ITER = 40
    real(dp), parameter :: X_TOL = 1.0e-12_dp
    !> p of chi^2 below this: the rows disagree with the fit beyond their u (self-check)
    real(dp), parameter :: CONSISTENCY_LEVEL = 0.05_dp
    !> Relative steps of the differences: the Jacobian, the inputs (linearised model /
    !! simulated periods).
    real(dp), parameter :: H_LIN = 1.0e-6_dp, H_SIM = 1.0e-5_dp
    real(dp), parameter :: HX_LIN = 1.0e-6_dp, HX_SIM = 1.0e-4_dp
    !> A Monte Carlo refit ends when each step is below this fraction of the entry's u.
    real(dp), parameter :: MC_STEP = 1.0e-3_dp
    !> Largest amplitude the limit search tries (degrees).
    real(dp), parameter :: LIMIT_SEARCH_MAX = 64.0_dp

contains

    ! ------------------------------------------------------------------ the problem

    !> The problem of a deck and its table of hangs: mass, g, accuracy and uncertainties
    !! from the deck (&tensor), the cases (hang, amplitude) of the rows.
    subroutine problem_of(ten, sus, bod, acc, m, prob)
        type(tensor_group_t), intent(in) :: ten         !! the deck's &tensor
        type(suspension_group_t), intent(in) :: sus     !! (g; a platform's points)
        type(body_group_t), intent(in) :: bod           !! (mass)
        type(accuracy_t), intent(in) :: acc             !! the deck's accuracy
        type(measurement_t), intent(in) :: m    !! its hangs (releases) and their timings
        type(tensor_problem_t), intent(out) :: prob
        prob%mass = bod%mass
        prob%g = sus%g
        prob%hangs = m%releases%hang
        prob%rows = m%obs
        prob%acc = acc
        prob%u%mass = ten%u(1)
        prob%u%rig = ten%u(2:5)
        prob%u%g = ten%u(6)
        prob%u%amplitude = ten%u(8)
        prob%u%direction = ten%u_direction*deg
        ! the fixture; its cg in the body frame is from the frame's origin, where the
        ! attachment points' form puts the mass centre at &tensor cg (up/along: at 0)
        prob%fix%mass = ten%fixture_mass
        prob%fix%cg = ten%fixture_cg
        prob%fix%inertia = ten%fixture_inertia
        prob%fix%hang_frame = trim(ten%fixture_frame) == 'hang'
        prob%u%fix_mass = ten%u_fixture_mass
        prob%u%fix_cg = ten%u_fixture_cg
        prob%u%fix_inertia = [ten%u_fixture_inertia(1, 1), ten%u_fixture_inertia(2, 2), &
            ten%u_fixture_inertia(3, 3), ten%u_fixture_inertia(1, 2), &
            ten%u_fixture_inertia(1, 3), ten%u_fixture_inertia(2, 3)]
        prob%u%attitude = ten%u_attitude*deg
        if (m%points) prob%origin = ten%cg
        prob%est_cg = ten%estimates_cg()
        prob%loaded = ten%has_fixture() .or. prob%est_cg
        prob%np = merge(9, 6, prob%est_cg)
        if (sus%cables == 3 .and. sus%pointwise()) then
            prob%pts%given = .true.
            prob%pts%support = sus%support_points(:, 1:3)
            prob%pts%body = sus%body_points(:, 1:3)
            prob%pts%lengths = sus%lengths(1:3)
            prob%pts%b = sus%b
            prob%pts%b_prime = sus%b_prime
            prob%pts%l = sus%l
        end if
        call set_cases(prob)
    end subroutine problem_of

    !> The cases of a problem's rows: one per distinct (hang, amplitude); u_def = 0.
    pure subroutine set_cases(prob)
        type(tensor_problem_t), intent(inout) :: prob
        integer :: i, j, n, nc
        n = size(prob%rows)
        allocate (prob%row_case(n), prob%case_hang(n), prob%case_amp(n))
        if (.not. allocated(prob%u_def)) then
            allocate (prob%u_def(n))
            prob%u_def = 0.0_dp
        end if
        nc = 0
        do i = 1, n
            prob%row_case(i) = 0
            do j = 1, nc
                if (prob%case_hang(j) == prob%rows(i)%release .and. &
                    prob%case_amp(j) == prob%rows(i)%amplitude) then
                    prob%row_case(i) = j
                    exit
                end if
            end do
            if (prob%row_case(i) == 0) then
                nc = nc + 1
                prob%case_hang(nc) = prob%rows(i)%release
                prob%case_amp(nc) = prob%rows(i)%amplitude
                prob%row_case(i) = nc
            end if
        end do
        prob%case_hang = prob%case_hang(1:nc)
        prob%case_amp = prob%case_amp(1:nc)
        prob%att_hang = pack([(i, i=1, size(prob%hangs))], prob%hangs%attitude .and. prob%est_cg)
    end subroutine set_cases

    !> 'hang ID (line L)' for messages.
    function hang_label(h) result(s)
        type(hang_t), intent(in) :: h
        character(len=:), allocatable :: s
        s = 'hang '//itoa(h%id)//' (line '//itoa(h%line)//')'
    end function hang_label

    ! ------------------------------------------------------------------ directions

    !> The 26 face, edge and corner directions of the body frame (unit): the faces x, -x,
    !! y, -y, z, -z, then the 12 edges and the 8 corners, each direction followed by its
    !! opposite.
    pure function candidate_directions() result(c)
        real(dp) :: c(3, 26)
        integer :: i, j, k, n, nz, f
        real(dp) :: v(3)
        n = 0
        do nz = 1, 3
            do i = 1, -1, -1
                do j = 1, -1, -1
                    do k = 1, -1, -1
                        if (count([i, j, k] /= 0) /= nz) cycle
                        ! the first nonzero component positive: each direction once
                        f = i
                        if (f == 0) f = j
                        if (f == 0) f = k
                        if (f < 0) cycle
                        v = real([i, j, k], dp)
                        n = n + 1
                        c(:, n) = v/norm2(v)
                        n = n + 1
                        c(:, n) = -v/norm2(v)
                    end do
                end do
            end do
        end do
    end function candidate_directions

    !> The along of a planned hang with up u: the first candidate direction normal to u.
    pure function along_for(u) result(a)
        real(dp), intent(in) :: u(3)            !! unit
        real(dp) :: a(3)
        real(dp) :: c(3, 26)
        integer :: k
        c = candidate_directions()
        a = c(:, 1)
        do k = 1, 26
            if (abs(dot_product(c(:, k), u)) < 1.0e-12_dp) then
                a = c(:, k)
                return
            end if
        end do
    end function along_for

    !> The distinct unit directions of up among the hangs (u and -u count as one), and the
    !! hang of each.
    pure subroutine distinct_directions(hangs, dirs, first, n)
        type(hang_t), intent(in) :: hangs(:)
        real(dp), intent(out) :: dirs(3, size(hangs))
        integer, intent(out) :: first(size(hangs))
        integer, intent(out) :: n
        integer :: h, k
        logical :: seen
        n = 0
        do h = 1, size(hangs)
            seen = .false.
            do k = 1, n
                if (abs(dot_product(dirs(:, k), hangs(h)%up)) > 1.0_dp - PARALLEL_TOL) then
                    seen = .true.
                    exit
                end if
            end do
            if (seen) cycle
            n = n + 1
            dirs(:, n) = hangs(h)%up
            first(n) = h
        end do
    end subroutine distinct_directions

    !> The condition number of the design matrix of unit directions (rows a(u)); huge
    !! when fewer than six or singular.
    function design_condition(dirs) result(cond)
        real(dp), intent(in) :: dirs(:, :)
        real(dp) :: cond
        real(dp), allocatable :: a(:, :), s(:)
        real(dp) :: vt(6, 6)
        type(status_t) :: st
        integer :: k, n
        n = size(dirs, 2)
        cond = huge(1.0_dp)
        if (n < 6) return
        allocate (a(n, 6), s(6))
        do k = 1, n
            a(k, :) = moment_direction(dirs(:, k))
        end do
        call la_svd(a, s, vt, st)
        if (st%code /= STATUS_OK) return
        if (s(6) > 0.0_dp) cond = s(1)/s(6)
    end function design_condition

    !> The hangs' directions determine the tensor: at least six distinct directions of up
    !! whose design matrix has condition <= COND_MAX; else ERR_DECK naming the face, edge or
    !! corner directions whose hangs would make it so (added greedily).
    subroutine check_directions(hangs, what, cond, stat)
        type(hang_t), intent(in) :: hangs(:)    !! the hangs
        character(len=*), intent(in) :: what    !! the table, for messages
        real(dp), intent(out) :: cond           !! the design matrix's condition
        type(status_t), intent(out) :: stat     !! ERR_DECK
        real(dp) :: dirs(3, size(hangs)), c(3, 26), best, cb
        real(dp), allocatable :: cur(:, :)
        integer :: first(size(hangs)), n, k, kb, added
        character(len=:), allocatable :: adds, head
        stat%code = STATUS_OK
        call distinct_directions(hangs, dirs, first, n)
        cond = design_condition(dirs(:, 1:n))
        if (n >= 6 .and. cond <= COND_MAX) return
        ! the candidates to add, one at a time, each the one that helps most
        c = candidate_directions()
        cur = dirs(:, 1:n)
        adds = ''
        do added = 1, 6
            kb = 0
            best = huge(1.0_dp)
            do k = 1, 26, 2
                if (any(abs(matmul(c(:, k), cur)) > 1.0_dp - PARALLEL_TOL)) cycle
                cb = score([cur, c(:, k)], size(cur, 2) + 1)
                if (cb < best) then
                    best = cb
                    kb = k
                end if
            end do
            if (kb == 0) exit
            cur = reshape([cur, c(:, kb)], [3, size(cur, 2) + 1])
            if (len(adds) > 0) adds = adds//'; '
            adds = adds//'('//dirtext(c(:, kb))//')'
            if (size(cur, 2) >= 6) then
                if (design_condition(cur) <= COND_MAX) exit
            end if
        end do
        if (n < 6) then
            head = what//': '//itoa(n)//' distinct direction'//trim(merge('s', ' ', n /= 1))// &
                ' of up among '//itoa(size(hangs))//' hang'//trim(merge('s', ' ', &
                size(hangs) /= 1))//' (u and -u count as one) cannot determine the six '// &
                'entries of the tensor'
        else
            head = what//': the '//itoa(n)//' directions of up have a design matrix of '// &
                'condition '//sci(min(cond, 1.0e300_dp), 2)//' (> '//rshort(COND_MAX)// &
                '): they do not determine the six entries of the tensor (coplanar or nearly so)'
        end if
        call set_error(stat, ERR_DECK, head//'; allowed: at least six directions, no two '// &
            'parallel, whose design matrix has condition <= '//rshort(COND_MAX)// &
            '; add hangs with up = '//adds//' (body frame)')
    contains
        !> How far a set of directions is from determining x: the condition when there are
        !! six or more, else minus the smallest of the nonzero singular values of a full set.
        function score(dd, m) result(sc)
            integer, intent(in) :: m
            real(dp), intent(in) :: dd(3, m)
            real(dp) :: sc
            real(dp), allocatable :: a(:, :), s(:), vt(:, :)
            type(status_t) :: st
            integer :: j, r
            allocate (a(m, 6), s(min(m, 6)), vt(6, 6))
            do j = 1, m
                a(j, :) = moment_direction(dd(:, j))
            end do
            call la_svd(a, s, vt, st)
            r = count(s > 1.0e-10_dp*s(1))
            ! more rank first, then the largest smallest singular value, then the condition
            sc = 1.0e6_dp*(6 - r) - s(max(1, r))
            if (r == 6) sc = -1.0e3_dp + min(1.0e2_dp, log10(s(1)/s(6)))
        end function score
    end subroutine check_directions

    !> A direction as text: its components to 4 digits.
    function dirtext(u) result(s)
        real(dp), intent(in) :: u(3)
        character(len=:), allocatable :: s
        real(dp) :: v(3)
        v = u/maxval(abs(u))
        s = rshort(anint(v(1)*1.0e4_dp)/1.0e4_dp)//', '//rshort(anint(v(2)*1.0e4_dp)/1.0e4_dp) &
            //', '//rshort(anint(v(3)*1.0e4_dp)/1.0e4_dp)
    end function dirtext

    ! ------------------------------------------------------------------ the projection

    !> The projection solution: each row's vertical moment by the linear formula
    !! m g b b' T^2 / (16 pi^2 l), l = (l + l')/2 of its hang, then least squares of
    !! a(up) . x on them.
    subroutine projection(prob, x, stat)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(out) :: x(6)
        type(status_t), intent(out) :: stat     !! ERR_NUMERIC from dgels
        real(dp), allocatable :: a(:, :), b(:)
        real(dp) :: mc, xf(6)
        type(hang_t) :: hc
        integer :: i, n, k
        n = size(prob%rows)
        allocate (a(n, 6), b(n))
        do i = 1, n
            associate (h => prob%hangs(prob%rows(i)%release))
                a(i, :) = moment_direction(h%up)
                b(i) = prob%mass*prob%g*h%b*h%b_prime*prob%rows(i)%period**2/ &
                       (16.0_dp*pi**2*0.5_dp*(h%l + h%l_prime))
                if (prob%loaded) then
                    ! with a fixture: the whole's moment by the formula, less the fixture's
                    ! share about the whole's vertical (the subtraction of the tool in use)
                    call loaded_hang(h, prob%mass, [(0.0_dp, k=1, 6)], prob%fix, prob%origin, &
                                     prob%dcg, hc, mc, xf, stat)
                    if (stat%code == STATUS_OK) then
                        a(i, :) = moment_direction(hc%up)
                        b(i) = mc*prob%g*h%b*h%b_prime*prob%rows(i)%period**2/ &
                               (16.0_dp*pi**2*0.5_dp*(h%l + h%l_prime)) - &
                               vertical_moment(xf, hc%up)
                    end if
                end if
            end associate
        end do
        call la_lstsq(a, b, x, stat)
        if (stat%code /= STATUS_OK) stat%msg = 'the projection solution: '//stat%msg
    end subroutine projection

    ! ------------------------------------------------------------------ model periods

    !> The model period of each case of the problem (hang_model's hang_period) at the
    !! tensor x; optionally with other hangs, mass, g (a perturbed problem).
    subroutine model_periods(prob, x, tc, stat)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: x(6)
        real(dp), intent(out) :: tc(:)          !! per case (s)
        type(status_t), intent(out) :: stat
        integer :: c
        tc = 0.0_dp
        stat%code = STATUS_OK
        do c = 1, size(prob%case_hang)
            call case_period(prob, prob%hangs(prob%case_hang(c)), prob%case_amp(c), &
                             prob%mass, prob%g, x, tc(c), stat)
            if (stat%code /= STATUS_OK) return
        end do
    end subroutine model_periods

    !> The period of hang h at amplitude amp for the tensor x, mass and g.
    subroutine case_period(prob, h, amp, mass, g, x, t, stat)
        type(tensor_problem_t), intent(in) :: prob
        type(hang_t), intent(in) :: h
        real(dp), intent(in) :: amp, mass, g, x(6)
        real(dp), intent(out) :: t
        type(status_t), intent(out) :: stat
        type(rig_t) :: rg
        t = 0.0_dp
        call problem_rig(prob, h, mass, g, x, rg, stat)
        if (stat%code == STATUS_OK) call hang_period(rg, prob%acc, amp, t, stat, prob%pts)
        if (stat%code /= STATUS_OK) stat%msg = hang_label(h)//': '//stat%msg
    end subroutine case_period

    !> The rig of hang h for the body's tensor x and mass: hang_rig, of the loaded hang
    !! (hang_model's loaded_hang: the body with its fixture, its mass centre where the
    !! problem puts it) when the problem has a fixture or fits the mass centre.
    subroutine problem_rig(prob, h, mass, g, x, rg, stat)
        type(tensor_problem_t), intent(in) :: prob
        type(hang_t), intent(in) :: h
        real(dp), intent(in) :: mass, g, x(6)
        type(rig_t), intent(out) :: rg
        type(status_t), intent(out) :: stat
        type(hang_t) :: hc
        real(dp) :: mc, xc(6)
        if (.not. prob%loaded) then
            call hang_rig(mass, g, h, x, rg, stat)
            return
        end if
        call loaded_hang(h, mass, x, prob%fix, prob%origin, prob%dcg, hc, mc, xc, stat)
        if (stat%code == STATUS_OK) call hang_rig(mc, g, hc, xc, rg, stat)
    end subroutine problem_rig

    !> The attitude residual of hang h: the sine of the angle between the measured gravity
    !! and the plane through C, D and the mass centre of what hangs (at rest gravity lies
    !! in that plane), rad.
    function attitude_residual(prob, h, mass) result(r)
        type(tensor_problem_t), intent(in) :: prob
        type(hang_t), intent(in) :: h
        real(dp), intent(in) :: mass
        real(dp) :: r
        real(dp) :: rf(3), jf(3, 3), g(3)
        call fixture_in_body(h, prob%fix, prob%origin, rf, jf)
        g = (mass*prob%dcg + prob%fix%mass*rf)/(mass + prob%fix%mass)
        r = dot_product(h%gravity, plane_normal(h, g))
    end function attitude_residual

    !> The step of the Jacobian's differences for the tensor x (relative to its size).
    pure real(dp) function x_step(prob, x)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: x(6)
        x_step = merge(H_SIM, H_LIN, any(prob%case_amp > 0.0_dp))*maxval(x(1:3))
    end function x_step

    !> dT/dx of each case by forward differences from tc (the periods at x).
    subroutine case_jacobian(prob, x, tc, a, stat)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: x(6), tc(:)
        real(dp), intent(out) :: a(:, :)        !! (cases, 6)
        type(status_t), intent(out) :: stat
        real(dp) :: xp(6), h, tp(size(tc))
        integer :: p
        h = x_step(prob, x)
        do p = 1, 6
            xp = x
            xp(p) = x(p) + h
            call model_periods(prob, xp, tp, stat)
            if (stat%code /= STATUS_OK) then
                stat%msg = 'the Jacobian: '//stat%msg
                return
            end if
            a(:, p) = (tp - tc)/h
        end do
    end subroutine case_jacobian

    !> The sensitivities of each case's period to its inputs at x (central differences;
    !! mass and g exactly): amplitude (per degree), the three rotations of the body (per
    !! rad), the hang's l, l_prime, b, b_prime, mass, g.
    subroutine case_sensitivities(prob, x, tc, a, s_amp, s_dir, s_rig, s_mass, s_g, ex, stat)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: x(6), tc(:), a(:, :)
        real(dp), intent(out) :: s_amp(:), s_dir(:, :), s_rig(:, :), s_mass(:), s_g(:)
        type(extra_sens_t), intent(out) :: ex   !! the fixture's and the attitudes'
        type(status_t), intent(out) :: stat
        type(hang_t) :: hp, hm
        real(dp) :: tp, tm, hx, ha, eps(3), v, dmore, dless, hstep
        integer :: c, k
        logical :: sim
        stat%code = STATUS_OK
        allocate (ex%fix(size(tc), 4))
        ex%fix = 0.0_dp
        do c = 1, size(tc)
            associate (h => prob%hangs(prob%case_hang(c)), amp => prob%case_amp(c))
                sim = amp > 0.0_dp
                hx = merge(HX_SIM, HX_LIN, sim)
                s_mass(c) = -dot_product(x, a(c, :))/prob%mass
                s_g(c) = -0.5_dp*tc(c)/prob%g
                ! with a fixture or a mass centre off the table's, the model does not see
                ! J/m alone: the mass, and the fixture's mass and mass centre, by differences
                if (prob%loaded) then
                    call case_period(prob, h, amp, prob%mass*(1.0_dp + hx), prob%g, x, tp, stat)
                    if (stat%code == STATUS_OK) call case_period(prob, h, amp, &
                        prob%mass*(1.0_dp - hx), prob%g, x, tm, stat)
                    if (stat%code /= STATUS_OK) return
                    s_mass(c) = (tp - tm)/(2.0_dp*hx*prob%mass)
                    do k = 1, 4
                        call fixture_diff(k, hx, dmore, dless, hstep)
                        if (stat%code /= STATUS_OK) return
                        ex%fix(c, k) = (dmore - dless)/(2.0_dp*hstep)
                    end do
                end if
                s_amp(c) = 0.0_dp
                if (sim) then
                    ha = min(0.5_dp*amp, max(1.0e-3_dp, 1.0e-2_dp*amp))
                    call case_period(prob, h, amp + ha, prob%mass, prob%g, x, tp, stat)
                    if (stat%code == STATUS_OK) &
                        call case_period(prob, h, amp - ha, prob%mass, prob%g, x, tm, stat)
                    if (stat%code /= STATUS_OK) return
                    s_amp(c) = (tp - tm)/(2.0_dp*ha)
                end if
                do k = 1, 3
                    eps = 0.0_dp
                    eps(k) = hx
                    hp = turned_hang(h, eps)
                    hm = turned_hang(h, -eps)
                    call case_period(prob, hp, amp, prob%mass, prob%g, x, tp, stat)
                    if (stat%code == STATUS_OK) &
                        call case_period(prob, hm, amp, prob%mass, prob%g, x, tm, stat)
                    if (stat%code /= STATUS_OK) return
                    s_dir(c, k) = (tp - tm)/(2.0_dp*hx)
                end do
                do k = 1, 4
                    hp = h
                    hm = h
                    v = rig_value(h, k)
                    call set_rig_value(hp, k, v*(1.0_dp + hx))
                    call set_rig_value(hm, k, v*(1.0_dp - hx))
                    call case_period(prob, hp, amp, prob%mass, prob%g, x, tp, stat)
                    if (stat%code == STATUS_OK) &
                        call case_period(prob, hm, amp, prob%mass, prob%g, x, tm, stat)
                    if (stat%code /= STATUS_OK) return
                    s_rig(c, k) = (tp - tm)/(2.0_dp*hx*v)
                end do
            end associate
        end do
        call attitude_sensitivities(prob, ex)
    contains
        !> The case's period with the fixture's input k (mass, cg x, y, z) moved by +- its
        !! step.
        subroutine fixture_diff(k, hx, tmore, tless, step)
            integer, intent(in) :: k
            real(dp), intent(in) :: hx
            real(dp), intent(out) :: tmore, tless, step
            type(tensor_problem_t) :: pq
            pq = prob
            if (k == 1) then
                step = hx*max(prob%fix%mass, prob%mass)
                pq%fix%mass = prob%fix%mass + step
            else
                step = hx*prob%hangs(prob%case_hang(c))%b_prime
                pq%fix%cg(k - 1) = prob%fix%cg(k - 1) + step
            end if
            call case_period(pq, prob%hangs(prob%case_hang(c)), prob%case_amp(c), prob%mass, &
                             prob%g, x, tmore, stat)
            if (stat%code /= STATUS_OK) return
            if (k == 1) then
                pq%fix%mass = prob%fix%mass - step
            else
                pq%fix%cg(k - 1) = prob%fix%cg(k - 1) - step
            end if
            call case_period(pq, prob%hangs(prob%case_hang(c)), prob%case_amp(c), prob%mass, &
                             prob%g, x, tless, stat)
        end subroutine fixture_diff
    end subroutine case_sensitivities

    !> The sensitivities of each attitude residual (central differences): the three
    !! rotations of its hang (per rad), the body's mass, the fixture's mass and mass centre.
    subroutine attitude_sensitivities(prob, ex)
        type(tensor_problem_t), intent(in) :: prob
        type(extra_sens_t), intent(inout) :: ex
        type(tensor_problem_t) :: pq
        real(dp) :: eps(3), hx, step
        integer :: j, k, na
        na = size(prob%att_hang)
        allocate (ex%att_dir(na, 3), ex%att_mass(na), ex%att_fix(na, 4))
        ex%att_dir = 0.0_dp
        ex%att_mass = 0.0_dp
        ex%att_fix = 0.0_dp
        if (na == 0) return
        hx = HX_LIN
        pq = prob
        do j = 1, na
            associate (h => prob%hangs(prob%att_hang(j)))
                do k = 1, 3
                    eps = 0.0_dp
                    eps(k) = hx
                    ex%att_dir(j, k) = (attitude_residual(prob, turned_hang(h, eps), prob%mass) &
                        - attitude_residual(prob, turned_hang(h, -eps), prob%mass))/(2.0_dp*hx)
                end do
                ex%att_mass(j) = (attitude_residual(prob, h, prob%mass*(1.0_dp + hx)) - &
                    attitude_residual(prob, h, prob%mass*(1.0_dp - hx)))/(2.0_dp*hx*prob%mass)
                step = hx*max(prob%fix%mass, prob%mass)
                pq%fix%mass = prob%fix%mass + step
                ex%att_fix(j, 1) = attitude_residual(pq, h, prob%mass)
                pq%fix%mass = prob%fix%mass - step
                ex%att_fix(j, 1) = (ex%att_fix(j, 1) - attitude_residual(pq, h, &
                                                        prob%mass))/(2.0_dp*step)
                pq%fix%mass = prob%fix%mass
                step = hx*h%b_prime
                do k = 1, 3
                    pq%fix%cg(k) = prob%fix%cg(k) + step
                    ex%att_fix(j, 1 + k) = attitude_residual(pq, h, prob%mass)
                    pq%fix%cg(k) = prob%fix%cg(k) - step
                    ex%att_fix(j, 1 + k) = (ex%att_fix(j, 1 + k) - attitude_residual(pq, h, &
                                                                    prob%mass))/(2.0_dp*step)
                    pq%fix%cg(k) = prob%fix%cg(k)
                end do
            end associate
        end do
    end subroutine attitude_sensitivities

    !> A hang's rig input k (l, l_prime, b, b_prime).
    pure real(dp) function rig_value(h, k) result(v)
        type(hang_t), intent(in) :: h
        integer, intent(in) :: k
        select case (k)
        case (1)
            v = h%l
        case (2)
            v = h%l_prime
        case (3)
            v = h%b
        case default
            v = h%b_prime
        end select
    end function rig_value

    !> Set a hang's rig input k; b_prime moves both attachment points symmetrically (the
    !! mass centre keeps its depth below CD and its offset from CD's midpoint).
    pure subroutine set_rig_value(h, k, v)
        type(hang_t), intent(inout) :: h
        integer, intent(in) :: k
        real(dp), intent(in) :: v
        select case (k)
        case (1)
            h%l = v
        case (2)
            h%l_prime = v
        case (3)
            h%b = v
        case default
            h%b_prime = v
        end select
    end subroutine set_rig_value

    ! ------------------------------------------------------------------ the fit

    !> The covariance blocks of the rows, one per hang: V = diag(u_T^2 + u_def^2 +
    !! (dT/dA u_A)^2) + sum over the three rotations and the hang's own rig of s s^T u^2;
    !! a row whose own diagonal part is zero adds U_FLOOR of its period.  none = .true. when no row has any
    !! stated uncertainty.
    subroutine row_covariance(prob, u_t, tc, s_amp, s_dir, s_rig, ex, blocks, none)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: u_t(:)          !! per row: the timing's u (s)
        real(dp), intent(in) :: tc(:), s_amp(:), s_dir(:, :), s_rig(:, :)
        type(extra_sens_t), intent(in) :: ex    !! the attitudes' sensitivities
        type(block_t), allocatable, intent(out) :: blocks(:)
        logical, intent(out) :: none
        integer :: h, m, i, j, k, n, ja
        integer, allocatable :: idx(:)
        real(dp) :: own
        real(dp), allocatable :: sd(:, :), sr(:, :), ov(:)
        allocate (blocks(size(prob%hangs)))
        none = .true.
        n = size(prob%rows)
        do h = 1, size(prob%hangs)
            ! the hang's rows, then its attitude (a residual of its own, after the rows)
            idx = pack([(i, i=1, n)], prob%rows%release == h)
            ja = 0
            if (size(prob%att_hang) > 0) ja = findloc(prob%att_hang, h, 1)
            if (ja > 0) idx = [idx, n + ja]
            m = size(idx)
            blocks(h)%rows = idx
            allocate (blocks(h)%l(m, m), sd(m, 3), sr(m, 4), ov(m))
            do j = 1, m
                if (idx(j) > n) then
                    sd(j, :) = ex%att_dir(ja, :)
                    sr(j, :) = 0.0_dp
                    ov(j) = prob%u%attitude**2
                    cycle
                end if
                sd(j, :) = s_dir(prob%row_case(idx(j)), :)
                sr(j, :) = s_rig(prob%row_case(idx(j)), :)
                ov(j) = u_t(idx(j))**2 + prob%u_def(idx(j))**2 + &
                    (s_amp(prob%row_case(idx(j)))*prob%u%amplitude)**2
            end do
            do j = 1, m
                do i = 1, m
                    blocks(h)%l(i, j) = sum(sd(i, :)*sd(j, :))*prob%u%direction**2
                    do k = 1, 4
                        if (prob%hangs(h)%own(k)) blocks(h)%l(i, j) = blocks(h)%l(i, j) + &
                            sr(i, k)*sr(j, k)*prob%u%rig(k)**2
                    end do
                end do
                own = ov(j)
                blocks(h)%l(j, j) = blocks(h)%l(j, j) + own
                if (blocks(h)%l(j, j) > 0.0_dp) none = .false.
                ! a row without a scatter of its own (rows of one case share the rest, and
                ! their block would be singular) counts U_FLOOR of its period
                if (.not. (own > 0.0_dp) .and. idx(j) <= n) &
                    blocks(h)%l(j, j) = blocks(h)%l(j, j) + (U_FLOOR*tc(prob%row_case(idx(j))))**2
            end do
            deallocate (sd, sr, ov)
        end do
    end subroutine row_covariance

    !> Factor each block: V = L L^T.
    subroutine factor_blocks(blocks, stat)
        type(block_t), intent(inout) :: blocks(:)
        type(status_t), intent(out) :: stat
        integer :: h
        stat%code = STATUS_OK
        do h = 1, size(blocks)
            call la_chol(blocks(h)%l, stat)
            if (stat%code /= STATUS_OK) then
                stat%msg = 'the covariance of the rows: '//stat%msg
                return
            end if
        end do
    end subroutine factor_blocks

    !> L^-1 b for the rows' factors, b (rows, any columns).
    subroutine whiten(blocks, b, stat)
        type(block_t), intent(in) :: blocks(:)
        real(dp), intent(inout) :: b(:, :)
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: part(:, :)
        integer :: h
        stat%code = STATUS_OK
        do h = 1, size(blocks)
            allocate (part(size(blocks(h)%rows), size(b, 2)))
            part(:, :) = b(blocks(h)%rows, :)
            call la_tri_solve(blocks(h)%l, part, stat)
            if (stat%code /= STATUS_OK) return
            b(blocks(h)%rows, :) = part
            deallocate (part)
        end do
    end subroutine whiten

    !> Gauss-Newton on the whitened residuals from x (see the module header), by the
    !! estimator with the step halved while it fails or raises the sum (by more than 1e-12
    !! of it), at most MAX_ITER Jacobians; converged when the step is below tol of the
    !! largest entry, or the sum falls by at most 1e-10 of itself, or, when no halving
    !! lowers the sum, the undamped step is below 1e3 tol (the model's resolution).  x is
    !! the solution on return, tc its periods, s its sum of squares; iters counts the
    !! Jacobians.
    subroutine gauss_newton(prob, blocks, x, tc, s, iters, evals, stat)
        type(tensor_problem_t), intent(in) :: prob
        type(block_t), intent(in) :: blocks(:)
        real(dp), intent(inout) :: x(:)         !! the entries (and the mass centre)
        real(dp), intent(out) :: tc(:), s
        integer, intent(inout) :: iters, evals
        type(status_t), intent(out) :: stat
        type(tensor_lsq_t) :: lsq
        type(lsq_options_t) :: opts
        type(lsq_result_t) :: res
        real(dp) :: tol, rr(size(prob%rows) + size(prob%att_hang))
        s = huge(1.0_dp)
        tc = 0.0_dp
        tol = X_TOL
        if (any(prob%case_amp > 0.0_dp)) tol = max(X_TOL, 10.0_dp*prob%acc%rtol)
        lsq%tp = prob
        lsq%blocks = blocks
        allocate (lsq%tc(size(tc)))
        opts%damping = DAMP_HALVING
        opts%lambda_max = 1.0e12_dp             ! 40 tries: the step down to 2^-39 of itself
        opts%rise = 1.0e-12_dp
        opts%max_iter = huge(1)
        opts%max_jacobians = MAX_ITER
        opts%gtol = 0.0_dp
        opts%xtol = tol
        opts%step_norm = STEP_LARGEST
        if (prob%est_cg) opts%step_norm = STEP_SCALED
        opts%ftol = 1.0e-10_dp
        opts%small_gain = huge(1.0_dp)
        opts%floor_gain = 0.0_dp
        opts%exact = 0.0_dp
        opts%floor_xtol = 1.0e3_dp*tol
        call estimate(lsq, x, opts, res, stat)
        iters = iters + res%jacobians
        evals = evals + res%evaluations
        if (res%converged) then
            x = res%p
            s = res%cost
            ! the model's periods at the solution (the last evaluation may be a step refused)
            if (.not. all(lsq%x_last(1:size(x)) == x)) call lsq%residual(x, rr, stat)
            tc = lsq%tc
            return
        end if
        select case (res%ended)
        case (FAIL_FLOOR)
            call set_error(stat, ERR_NUMERIC, 'the fit of the tensor: no Gauss-Newton step '// &
                'lowers the misfit (at the entries '//rlist_short(res%p)//'); check that the '// &
                'periods agree with each other and with the rig')
        case (FAIL_ITERATIONS)
            call set_error(stat, ERR_NUMERIC, 'the fit of the tensor did not converge in '// &
                itoa(MAX_ITER)//' Gauss-Newton iterations (entries '//rlist_short(res%p)// &
                '); check that the periods agree with each other and with the rig')
        end select
    end subroutine gauss_newton

    !> The whitened residuals L^-1 (T(x) - T measured) of the rows (the model's periods of
    !! the cases kept: tc at x_last).
    subroutine tensor_residual(prob, p, r, stat)
        class(tensor_lsq_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)            !! the six entries
        real(dp), intent(out) :: r(:)
        type(status_t), intent(out) :: stat
        real(dp) :: rr(size(r), 1)
        integer :: n, j
        r = 0.0_dp
        prob%x_last = huge(1.0_dp)
        if (prob%tp%est_cg) prob%tp%dcg = p(7:9)
        call model_periods(prob%tp, p(1:6), prob%tc, stat)
        if (stat%code /= STATUS_OK) return
        n = size(prob%tp%rows)
        rr(1:n, 1) = prob%tc(prob%tp%row_case) - prob%tp%rows%period
        do j = 1, size(prob%tp%att_hang)
            rr(n + j, 1) = attitude_residual(prob%tp, prob%tp%hangs(prob%tp%att_hang(j)), &
                                             prob%tp%mass)
        end do
        call whiten(prob%blocks, rr, stat)
        if (stat%code /= STATUS_OK) return
        r = rr(:, 1)
        prob%x_last(1:size(p)) = p
    end subroutine tensor_residual

    !> The number of rows.
    pure integer function tensor_nres(prob) result(n)
        class(tensor_lsq_t), intent(in) :: prob
        n = size(prob%tp%rows) + size(prob%tp%att_hang)
    end function tensor_nres

    !> The whitened Jacobian L^-1 dT/dx of the rows (case_jacobian: forward differences of
    !! the model from its periods at p).
    subroutine tensor_jacobian(prob, p, r, h, jac, evaluations, stat)
        class(tensor_lsq_t), intent(inout) :: prob
        real(dp), intent(in) :: p(:)            !! the six entries
        real(dp), intent(in) :: r(:)            !! r(p)
        real(dp), intent(in) :: h(:)            !! (not used: case_jacobian's own steps)
        real(dp), intent(out) :: jac(:, :)
        integer, intent(out) :: evaluations
        type(status_t), intent(out) :: stat
        real(dp) :: a(size(prob%tc), 6), rr(size(r)), tp(size(prob%tc)), hc
        type(tensor_problem_t) :: pq
        integer :: n, j, k
        evaluations = 0
        jac = 0.0_dp
        call unused(h)
        if (.not. all(prob%x_last(1:size(p)) == p)) then
            call prob%residual(p, rr, stat)
            evaluations = 1
            if (stat%code /= STATUS_OK) return
        end if
        call case_jacobian(prob%tp, p(1:6), prob%tc, a, stat)
        evaluations = evaluations + 6
        if (stat%code /= STATUS_OK) return
        n = size(prob%tp%rows)
        jac(1:n, 1:6) = a(prob%tp%row_case, :)
        if (prob%tp%est_cg) then
            ! the mass centre's columns: forward differences of the periods and attitudes
            hc = merge(H_SIM, H_LIN, any(prob%tp%case_amp > 0.0_dp))*prob%tp%hangs(1)%b_prime
            do k = 1, 3
                pq = prob%tp
                pq%dcg(k) = pq%dcg(k) + hc
                call model_periods(pq, p(1:6), tp, stat)
                if (stat%code /= STATUS_OK) return
                evaluations = evaluations + 1
                jac(1:n, 6 + k) = (tp(prob%tp%row_case) - prob%tc(prob%tp%row_case))/hc
                do j = 1, size(pq%att_hang)
                    associate (hh => pq%hangs(pq%att_hang(j)))
                        jac(n + j, 6 + k) = (attitude_residual(pq, hh, pq%mass) - &
                            attitude_residual(prob%tp, hh, pq%mass))/hc
                    end associate
                end do
            end do
        end if
        call whiten(prob%blocks, jac, stat)
    end subroutine tensor_jacobian

    !> The fit of the tensor from x0 with its first-order uncertainty (see the module
    !! header).
    subroutine fit_tensor(prob, x0, fit, stat)
        type(tensor_problem_t), intent(in) :: prob  !! the problem (u_def set)
        real(dp), intent(in) :: x0(6)           !! start (the projection solution)
        type(tensor_fit_t), intent(out) :: fit
        type(status_t), intent(out) :: stat     !! ERR_NUMERIC, ERR_DECK
        type(tensor_problem_t) :: pr
        type(block_t), allocatable :: blocks(:)
        type(extra_sens_t) :: ex
        real(dp), allocatable :: tc(:), a(:, :), s_amp(:), s_dir(:, :), s_rig(:, :)
        real(dp), allocatable :: s_mass(:), s_g(:), u_t(:), aw(:, :), r(:, :), pv(:)
        real(dp) :: x(6), s, w(3), v(3, 3)
        integer :: n, nc, na, round, j
        logical :: none
        pr = prob
        n = size(prob%rows)
        nc = size(prob%case_hang)
        na = size(prob%att_hang)
        allocate (tc(nc), a(nc, 6), s_amp(nc), s_dir(nc, 3), s_rig(nc, 4), s_mass(nc), &
                  s_g(nc), u_t(n))
        u_t = prob%rows%u_period
        fit%x_proj = x0
        x = x0
        ! a start that is not positive definite (noisy periods): its moments raised
        call principal_axes(x, w, v, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. (w(1) > 1.0e-3_dp*w(3))) then
            w = max(w, 1.0e-3_dp*abs(w(3)), tiny(1.0_dp))
            x = tensor_entries(matmul(v, matmul(diag3(w), transpose(v))))
        end if
        call model_periods(pr, x, tc, stat)
        if (stat%code /= STATUS_OK) then
            stat%msg = 'the model at the projection solution: '//stat%msg
            return
        end if
        pv = [x, pr%dcg]
        pv = pv(1:prob%np)
        do round = 1, 2
            call case_jacobian(pr, x, tc, a, stat)
            if (stat%code /= STATUS_OK) return
            call case_sensitivities(pr, x, tc, a, s_amp, s_dir, s_rig, s_mass, s_g, ex, stat)
            if (stat%code /= STATUS_OK) return
            fit%evaluations = fit%evaluations + 6 + 2*nc*8
            call row_covariance(pr, u_t, tc, s_amp, s_dir, s_rig, ex, blocks, none)
            if (none .and. .not. fit%scatter) then
                ! no stated uncertainty: equal weights, then the timing u from the scatter
                fit%scatter = .true.
                blocks = unit_blocks(blocks)
            else if (fit%scatter) then
                blocks = unit_blocks(blocks)
            end if
            call factor_blocks(blocks, stat)
            if (stat%code /= STATUS_OK) return
            call gauss_newton(pr, blocks, pv, tc, s, fit%iterations, fit%evaluations, stat)
            if (stat%code /= STATUS_OK) return
            x = pv(1:6)
            if (prob%est_cg) pr%dcg = pv(7:9)
        end do
        ! the final Jacobian and sensitivities at the solution
        call case_jacobian(pr, x, tc, a, stat)
        if (stat%code /= STATUS_OK) return
        call case_sensitivities(pr, x, tc, a, s_amp, s_dir, s_rig, s_mass, s_g, ex, stat)
        if (stat%code /= STATUS_OK) return
        fit%evaluations = fit%evaluations + 6 + 2*nc*8
        fit%dof = n + na - prob%np
        if (fit%scatter) then
            fit%u_scatter = 0.0_dp
            if (fit%dof > 0) fit%u_scatter = sqrt(sum((tc(prob%row_case) - &
                                                       prob%rows%period)**2)/fit%dof)
            u_t = fit%u_scatter
        end if
        call row_covariance(pr, u_t, tc, s_amp, s_dir, s_rig, ex, blocks, none)
        if (fit%scatter .and. fit%u_scatter == 0.0_dp) blocks = unit_blocks(blocks)
        call factor_blocks(blocks, stat)
        if (stat%code /= STATUS_OK) return
        fit%x = x
        fit%dcg = pr%dcg
        fit%model_period = tc(prob%row_case)
        fit%u_row = u_t
        ! chi-square of the rows (and the attitudes) against the fit
        allocate (r(n + na, 1), aw(n + na, prob%np))
        r(1:n, 1) = tc(prob%row_case) - prob%rows%period
        do j = 1, na
            r(n + j, 1) = attitude_residual(pr, pr%hangs(pr%att_hang(j)), pr%mass)
        end do
        call whiten(blocks, r, stat)
        if (stat%code /= STATUS_OK) return
        fit%chi2 = sum(r**2)
        if (fit%scatter) fit%chi2 = real(max(fit%dof, 0), dp)
        fit%p_value = 1.0_dp
        if (fit%dof > 0) fit%p_value = chi2_sf(fit%chi2, real(fit%dof, dp))
        fit%tested = .not. fit%scatter .and. fit%dof > 0
        if (fit%dof > 0) fit%birge = sqrt(fit%chi2/fit%dof)
        if (fit%tested .and. fit%p_value < CONSISTENCY_LEVEL) then
            fit%consistent = .false.
            fit%inflation = max(1.0_dp, fit%birge)
        end if
        aw = 0.0_dp
        aw(1:n, 1:6) = a(prob%row_case, :)
        if (prob%est_cg) call cg_columns(pr, x, tc, aw, stat)
        if (stat%code /= STATUS_OK) return
        call whiten(blocks, aw, stat)
        if (stat%code /= STATUS_OK) return
        fit%att_resid = r(n + 1:n + na, 1)
        call covariance_and_budget(pr, blocks, x, aw, u_t, s_amp, s_dir, s_rig, &
                                   s_mass, s_g, ex, a, fit, stat)
        if (stat%code /= STATUS_OK) return
        call per_hang(pr, blocks, x, tc, a, fit, stat)
    end subroutine fit_tensor

    !> The columns of the mass centre (7 to 9) of the rows' and attitudes' Jacobian, not
    !! whitened: central differences of the periods and the attitude residuals.
    subroutine cg_columns(prob, x, tc, aw, stat)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: x(6), tc(:)
        real(dp), intent(inout) :: aw(:, :)
        type(status_t), intent(out) :: stat
        type(tensor_problem_t) :: pp, pm
        real(dp) :: tp(size(tc)), tm(size(tc)), hc
        integer :: k, j, n
        n = size(prob%rows)
        hc = merge(H_SIM, H_LIN, any(prob%case_amp > 0.0_dp))*prob%hangs(1)%b_prime
        do k = 1, 3
            pp = prob
            pm = prob
            pp%dcg(k) = prob%dcg(k) + hc
            pm%dcg(k) = prob%dcg(k) - hc
            call model_periods(pp, x, tp, stat)
            if (stat%code == STATUS_OK) call model_periods(pm, x, tm, stat)
            if (stat%code /= STATUS_OK) return
            aw(1:n, 6 + k) = (tp(prob%row_case) - tm(prob%row_case))/(2.0_dp*hc)
            do j = 1, size(prob%att_hang)
                associate (hh => prob%hangs(prob%att_hang(j)))
                    aw(n + j, 6 + k) = (attitude_residual(pp, hh, prob%mass) - &
                        attitude_residual(pm, hh, prob%mass))/(2.0_dp*hc)
                end associate
            end do
        end do
    end subroutine cg_columns

    !> Blocks of the identity (equal weights) of the same shapes.
    pure function unit_blocks(b) result(u)
        type(block_t), intent(in) :: b(:)
        type(block_t) :: u(size(b))
        integer :: h, j
        do h = 1, size(b)
            u(h)%rows = b(h)%rows
            allocate (u(h)%l(size(b(h)%rows), size(b(h)%rows)))
            u(h)%l = 0.0_dp
            do j = 1, size(b(h)%rows)
                u(h)%l(j, j) = 1.0_dp
            end do
        end do
    end function unit_blocks

    pure function diag3(w) result(m)
        real(dp), intent(in) :: w(3)
        real(dp) :: m(3, 3)
        m = 0.0_dp
        m(1, 1) = w(1)
        m(2, 2) = w(2)
        m(3, 3) = w(3)
    end function diag3

    !> The covariance of x (sum over the inputs of S_k S_k^T u_k^2), the budget, the
    !! principal moments and axes with their u, coverage factors, the chord for Monte Carlo.
    subroutine covariance_and_budget(prob, blocks, x, aw, u_t, s_amp, s_dir, s_rig, &
                                     s_mass, s_g, ex, a, fit, stat)
        type(tensor_problem_t), intent(in) :: prob
        type(block_t), intent(in) :: blocks(:)
        real(dp), intent(in) :: x(6), aw(:, :), u_t(:)
        real(dp), intent(in) :: s_amp(:), s_dir(:, :), s_rig(:, :), s_mass(:), s_g(:)
        type(extra_sens_t), intent(in) :: ex    !! the fixture's and the attitudes'
        real(dp), intent(in) :: a(:, :)         !! dT/dx per case
        type(tensor_fit_t), intent(inout) :: fit
        type(status_t), intent(out) :: stat
        real(dp) :: sv(prob%np), vt(prob%np, prob%np), ninv(prob%np, prob%np), g(6)
        real(dp), allocatable :: gmat(:, :), col(:, :), gt(:, :)
        real(dp), allocatable :: cmoment(:, :)       ! per budget row: contribution to moments
        integer :: n, i, h, k, j, np, na, ja
        real(dp) :: cgrp(prob%np, prob%np), fi
        integer :: n_common
        n = size(prob%rows)
        np = prob%np
        na = size(prob%att_hang)
        fi = fit%inflation                      ! the per-hang sources' (the self-check)
        call la_svd(aw, sv, vt, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. (sv(np) > 1.0e-14_dp*sv(1))) then
            call set_error(stat, ERR_NUMERIC, 'the fit''s Jacobian is singular: the hangs do '// &
                'not determine the tensor'//trim(merge(' and the mass centre', &
                '                    ', prob%est_cg)))
            return
        end if
        ninv = 0.0_dp
        do k = 1, np
            ninv = ninv + outer(vt(k, :), vt(k, :))/sv(k)**2
        end do
        ! the chord: dx = -G L^-1 r, G = (A_w^T A_w)^-1 A_w^T; per block (G L^-1)^T =
        ! L^-T G^T
        gmat = matmul(ninv, transpose(aw))
        allocate (fit%chord(np, n + na), fit%cov_all(np, np))
        fit%cov_all = 0.0_dp
        do h = 1, size(blocks)
            gt = transpose(gmat(:, blocks(h)%rows))
            call la_tri_solve(blocks(h)%l, gt, stat, transposed=.true.)
            if (stat%code /= STATUS_OK) return
            fit%chord(:, blocks(h)%rows) = transpose(gt)
        end do
        ! the budget: one group per common input, and per hang its timing, amplitude,
        ! definition, direction and own rig inputs
        allocate (fit%budget(0), cmoment(3, 0))
        fit%cov = 0.0_dp
        call principal_axes(x, fit%moments, fit%axes, stat)
        if (stat%code /= STATUS_OK) return
        allocate (col(n + na, 1))
        ! mass, g
        call group('mass', prob%u%mass, [ (s_mass(prob%row_case(i)), i=1, n), ex%att_mass ])
        call group('g', prob%u%g, [ (s_g(prob%row_case(i)), i=1, n) ])
        do k = 1, 4
            col(:, 1) = 0.0_dp
            do i = 1, n
                if (.not. prob%hangs(prob%rows(i)%release)%own(k)) &
                    col(i, 1) = s_rig(prob%row_case(i), k)
            end do
            if (any(col(:, 1) /= 0.0_dp)) call group(trim(RIG_COLUMNS(k)), prob%u%rig(k), &
                                                     col(:, 1))
        end do
        ! the fixture: its mass, its mass centre (3), its inertia (6 entries)
        if (prob%u%fix_mass > 0.0_dp) call group('fixture_mass', prob%u%fix_mass, &
            [ (ex%fix(prob%row_case(i), 1), i=1, n), ex%att_fix(:, 1) ])
        if (any(prob%u%fix_cg > 0.0_dp)) then
            cgrp = 0.0_dp
            do k = 1, 3
                call add_input([ (ex%fix(prob%row_case(i), 1 + k), i=1, n), &
                               ex%att_fix(:, 1 + k) ], prob%u%fix_cg(k), cgrp)
            end do
            call push('fixture_cg', maxval(prob%u%fix_cg), cgrp, ROW_INPUT)
        end if
        if (any(prob%u%fix_inertia > 0.0_dp)) then
            cgrp = 0.0_dp
            do k = 1, 6
                col(:, 1) = 0.0_dp
                do i = 1, n
                    col(i, 1) = dot_product(a(prob%row_case(i), :), &
                        fixture_entry(prob%hangs(prob%rows(i)%release), k))
                end do
                call add_input(col(:, 1), prob%u%fix_inertia(k), cgrp)
            end do
            call push('fixture_inertia', maxval(prob%u%fix_inertia), cgrp, ROW_INPUT)
        end if
        n_common = size(fit%budget)
        do h = 1, size(prob%hangs)
            ! the timings of its rows
            cgrp = 0.0_dp
            do i = 1, n
                if (prob%rows(i)%release /= h) cycle
                col(:, 1) = 0.0_dp
                col(i, 1) = -1.0_dp
                call add_input(col(:, 1), fi*u_t(i), cgrp)
            end do
            call push('period('//itoa(prob%hangs(h)%id)//')', fi*u_t(first_row(h)), cgrp, &
                      ROW_TIMING)
            ! amplitudes
            if (prob%u%amplitude > 0.0_dp .and. any(prob%case_amp(pack(prob%row_case, &
                prob%rows%release == h)) > 0.0_dp)) then
                cgrp = 0.0_dp
                do i = 1, n
                    if (prob%rows(i)%release /= h) cycle
                    col(:, 1) = 0.0_dp
                    col(i, 1) = s_amp(prob%row_case(i))
                    call add_input(col(:, 1), fi*prob%u%amplitude, cgrp)
                end do
                call push('amplitude('//itoa(prob%hangs(h)%id)//')', fi*prob%u%amplitude, cgrp, &
                          ROW_AMPLITUDE)
            end if
            ! the period's definition (the drift of the maxima)
            if (any(prob%u_def(pack([(i, i=1, n)], prob%rows%release == h)) > 0.0_dp)) then
                cgrp = 0.0_dp
                do i = 1, n
                    if (prob%rows(i)%release /= h) cycle
                    col(:, 1) = 0.0_dp
                    col(i, 1) = -1.0_dp
                    call add_input(col(:, 1), fi*prob%u_def(i), cgrp)
                end do
                call push('definition('//itoa(prob%hangs(h)%id)//')', &
                          fi*maxval(prob%u_def(pack([(i, i=1, n)], prob%rows%release == h))), &
                          cgrp, ROW_DEFINITION)
            end if
            ! the direction: three rotations shared by its rows (and its attitude)
            ja = 0
            if (na > 0) ja = findloc(prob%att_hang, h, 1)
            if (prob%u%direction > 0.0_dp) then
                cgrp = 0.0_dp
                do k = 1, 3
                    col(:, 1) = 0.0_dp
                    do i = 1, n
                        if (prob%rows(i)%release == h) col(i, 1) = s_dir(prob%row_case(i), k)
                    end do
                    if (ja > 0) col(n + ja, 1) = ex%att_dir(ja, k)
                    call add_input(col(:, 1), fi*prob%u%direction, cgrp)
                end do
                call push('direction('//itoa(prob%hangs(h)%id)//')', fi*prob%u%direction/deg, &
                          cgrp, ROW_DIRECTION)
            end if
            ! its own rig
            do k = 1, 4
                if (.not. prob%hangs(h)%own(k)) cycle
                cgrp = 0.0_dp
                col(:, 1) = 0.0_dp
                do i = 1, n
                    if (prob%rows(i)%release == h) col(i, 1) = s_rig(prob%row_case(i), k)
                end do
                call add_input(col(:, 1), fi*prob%u%rig(k), cgrp)
                call push(trim(RIG_COLUMNS(k))//'('//itoa(prob%hangs(h)%id)//')', &
                          fi*prob%u%rig(k), cgrp, ROW_INPUT)
            end do
            ! its attitude as measured
            if (ja > 0) then
                cgrp = 0.0_dp
                col(:, 1) = 0.0_dp
                col(n + ja, 1) = -1.0_dp
                call add_input(col(:, 1), fi*prob%u%attitude, cgrp)
                call push('attitude('//itoa(prob%hangs(h)%id)//')', fi*prob%u%attitude/deg, &
                          cgrp, ROW_INPUT)
            end if
        end do
        fit%cov = fit%cov_all(1:6, 1:6)
        fit%u_x = sqrt(max(0.0_dp, [(fit%cov(k, k), k=1, 6)]))
        if (prob%est_cg) fit%u_dcg = sqrt(max(0.0_dp, [(fit%cov_all(k, k), k=7, 9)]))
        ! the principal moments and axes
        do k = 1, 3
            g = moment_direction(fit%axes(:, k))
            fit%u_moments(k) = sqrt(max(0.0_dp, dot_product(g, matmul(fit%cov, g))))
            ! the turn toward axis j: (v_j . dJ v_k)/(I_k - I_j); 90 degrees (undetermined)
            ! when the moments are too close for it
            fit%u_axes(k) = 0.0_dp
            do j = 1, 3
                if (j == k) cycle
                g = mixed(fit%axes(:, j), fit%axes(:, k))
                if (abs(fit%moments(k) - fit%moments(j)) > 1.0e-12_dp*fit%moments(3)) then
                    fit%u_axes(k) = fit%u_axes(k) + min(1.0e4_dp, &
                        dot_product(g, matmul(fit%cov, g))/(fit%moments(k) - fit%moments(j))**2)
                else
                    fit%u_axes(k) = 1.0e4_dp
                end if
            end do
            fit%u_axes(k) = min(90.0_dp, sqrt(max(0.0_dp, fit%u_axes(k)))/deg)
            ! effective degrees of freedom: the timing from the scatter has dof, all else
            ! is Type B
            fit%nu_eff(k) = NU_INFINITE
            if (fit%scatter .and. fit%dof > 0) then
                fit%nu_eff(k) = welch_satterthwaite(cmoment(k, :), &
                    [(merge(real(fit%dof, dp), 0.0_dp, fit%budget(j)%kind == ROW_TIMING), &
                      j=1, size(fit%budget))])
            else if (fi > 1.0_dp) then
                ! the per-hang rows inflated by the Birge ratio: its dof (the mass, g and
                ! the deck's rig rows, the first, are Type B)
                fit%nu_eff(k) = welch_satterthwaite(cmoment(k, :), &
                    [(merge(real(fit%dof, dp), 0.0_dp, j > n_common), j=1, size(fit%budget))])
            end if
            fit%k95(k) = coverage_factor(fit%nu_eff(k), 0.95_dp)
        end do
    contains
        !> A common input's group: its column of dr/dx over every row.
        subroutine group(name, u, dr)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: u, dr(:)
            real(dp) :: cg(np, np)
            cg = 0.0_dp
            call add_input(dr, u, cg)
            call push(name, u, cg, ROW_INPUT)
        end subroutine group
        !> S = -G L^-1 dr: its covariance S S^T u^2 added to cg and to fit%cov.
        subroutine add_input(dr, u, cg)
            real(dp), intent(in) :: dr(:), u       !! over the rows (then the attitudes)
            real(dp), intent(inout) :: cg(np, np)
            real(dp) :: sk(np)
            if (.not. (u > 0.0_dp)) return
            sk = -matmul(fit%chord(:, 1:size(dr)), dr)
            cg = cg + outer(sk, sk)*u**2
            fit%cov_all = fit%cov_all + outer(sk, sk)*u**2
        end subroutine add_input
        !> The change of the entries of what hangs in hang hh for a unit change of the
        !! fixture's inertia entry k (xx, yy, zz, xy, xz, yz, in the fixture's frame).
        function fixture_entry(hh, k) result(e)
            type(hang_t), intent(in) :: hh
            integer, intent(in) :: k
            real(dp) :: e(6), m(3, 3), r(3, 3)
            integer, parameter :: IK(6) = [1, 2, 3, 1, 1, 2], JK(6) = [1, 2, 3, 2, 3, 3]
            m = 0.0_dp
            m(IK(k), JK(k)) = 1.0_dp
            m(JK(k), IK(k)) = 1.0_dp
            if (prob%fix%hang_frame) then
                r(:, 1) = hh%along
                r(:, 2) = cross(hh%up, hh%along)
                r(:, 3) = hh%up
                m = matmul(r, matmul(m, transpose(r)))
            end if
            e = tensor_entries(m)
        end function fixture_entry
        !> One budget line from a group's covariance.
        subroutine push(name, u, cg, kind)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: u, cg(np, np)
            integer, intent(in) :: kind         !! ROW_* of module budget
            type(tensor_budget_row_t) :: row
            real(dp) :: cm(3, 1), gg(6)
            integer :: m
            row%input = name
            row%kind = kind
            row%u = u
            row%contribution = sqrt(max(0.0_dp, [(cg(m, m), m=1, 6)]))
            fit%budget = [fit%budget, row]
            do m = 1, 3
                gg = moment_direction(fit%axes(:, m))
                cm(m, 1) = sqrt(max(0.0_dp, dot_product(gg, matmul(cg(1:6, 1:6), gg))))
            end do
            cmoment = reshape([cmoment, cm], [3, size(cmoment, 2) + 1])
        end subroutine push
        pure integer function first_row(hh)
            integer, intent(in) :: hh
            first_row = findloc(prob%rows%release, hh, 1)
        end function first_row
    end subroutine covariance_and_budget

    pure function outer(a, b) result(m)
        real(dp), intent(in) :: a(:), b(:)
        real(dp) :: m(size(a), size(b))
        integer :: i
        do i = 1, size(b)
            m(:, i) = a*b(i)
        end do
    end function outer

    !> The row of v . J w in the entries: v . J w = sum_k m(k) x(k).
    pure function mixed(v, w) result(m)
        real(dp), intent(in) :: v(3), w(3)
        real(dp) :: m(6)
        m = [v(1)*w(1), v(2)*w(2), v(3)*w(3), v(1)*w(2) + v(2)*w(1), v(1)*w(3) + v(3)*w(1), &
             v(2)*w(3) + v(3)*w(2)]
    end function mixed

    !> Per hang: the vertical moment its rows measure, its u and normalised residual; the
    !! projection difference.
    subroutine per_hang(prob, blocks, x, tc, a, fit, stat)
        type(tensor_problem_t), intent(in) :: prob
        type(block_t), intent(in) :: blocks(:)
        real(dp), intent(in) :: x(6), tc(:), a(:, :)
        type(tensor_fit_t), intent(inout) :: fit
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: q(:, :), r(:, :)
        real(dp) :: qq(6), aa, delta
        integer :: h, nh, m, j
        nh = size(prob%hangs)
        allocate (fit%iv_fit(nh), fit%iv(nh), fit%u_iv(nh), fit%resid(nh))
        stat%code = STATUS_OK
        do h = 1, nh
            associate (idx => blocks(h)%rows, u => prob%hangs(h)%up)
                m = size(idx)
                ! dx for a unit change of u . J u alone: dJ = u u^T
                qq = [u(1)**2, u(2)**2, u(3)**2, u(1)*u(2), u(1)*u(3), u(2)*u(3)]
                allocate (q(m, 1), r(m, 1))
                do j = 1, m
                    if (idx(j) > size(prob%rows)) then
                        ! the hang's attitude: no moment in it
                        q(j, 1) = 0.0_dp
                        r(j, 1) = -attitude_residual(prob, prob%hangs(h), prob%mass)
                    else
                        q(j, 1) = dot_product(a(prob%row_case(idx(j)), :), qq)
                        r(j, 1) = prob%rows(idx(j))%period - tc(prob%row_case(idx(j)))
                    end if
                end do
                call la_tri_solve(blocks(h)%l, q, stat)
                if (stat%code == STATUS_OK) call la_tri_solve(blocks(h)%l, r, stat)
                if (stat%code /= STATUS_OK) return
                aa = sum(q**2)
                fit%iv_fit(h) = vertical_moment(x, u)
                delta = 0.0_dp
                fit%u_iv(h) = 0.0_dp
                if (aa > 0.0_dp) then
                    delta = sum(q*r)/aa
                    fit%u_iv(h) = 1.0_dp/sqrt(aa)
                end if
                if (fit%scatter .and. fit%u_scatter == 0.0_dp) fit%u_iv(h) = 0.0_dp
                fit%iv(h) = fit%iv_fit(h) + delta
                fit%resid(h) = 0.0_dp
                if (fit%u_iv(h) > 0.0_dp) fit%resid(h) = delta/fit%u_iv(h)
                deallocate (q, r)
            end associate
        end do
        fit%projection_difference = maxval(abs(fit%x_proj - x))/maxval(fit%moments)
    end subroutine per_hang

    ! ------------------------------------------------------------------ amplitude limit

    !> The drift of theta_4's maxima of each row at its amplitude (0 at 0) for the tensor x,
    !! and each hang's amplitude limit: the largest amplitude (degrees, to 2 digits) with a
    !! drift <= DRIFT_MAX, LIMIT_SEARCH_MAX when none up to it drifts more.
    subroutine amplitude_limits(prob, x, drift, limit, stat)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: x(6)
        real(dp), intent(out) :: drift(:)       !! per row
        real(dp), intent(out) :: limit(:)       !! per hang, degrees
        type(status_t), intent(out) :: stat
        real(dp), allocatable :: dc(:)
        real(dp) :: lo, hi, mid, dm
        type(rig_t) :: rg
        integer :: c, h, k
        stat%code = STATUS_OK
        allocate (dc(size(prob%case_hang)))
        dc = 0.0_dp
        do c = 1, size(prob%case_hang)
            if (prob%case_amp(c) <= 0.0_dp) cycle
            call drift_at(prob%hangs(prob%case_hang(c)), prob%case_amp(c), dc(c), stat)
            if (stat%code /= STATUS_OK) return
        end do
        drift = dc(prob%row_case)
        do h = 1, size(prob%hangs)
            lo = 0.0_dp
            hi = 1.0_dp
            do
                call drift_at(prob%hangs(h), hi, dm, stat)
                if (stat%code /= STATUS_OK) then
                    stat%code = STATUS_OK
                    dm = huge(1.0_dp)
                end if
                if (dm > DRIFT_MAX) exit
                lo = hi
                if (hi >= LIMIT_SEARCH_MAX) exit
                hi = min(LIMIT_SEARCH_MAX, 2.0_dp*hi)
            end do
            if (lo < hi) then
                do k = 1, 5
                    if (lo > 0.0_dp) then
                        mid = sqrt(lo*hi)
                    else
                        mid = 0.5_dp*hi
                    end if
                    call drift_at(prob%hangs(h), mid, dm, stat)
                    if (stat%code /= STATUS_OK) then
                        stat%code = STATUS_OK
                        dm = huge(1.0_dp)
                    end if
                    if (dm > DRIFT_MAX) then
                        hi = mid
                    else
                        lo = mid
                    end if
                end do
            end if
            limit(h) = round2(lo)
        end do
    contains
        subroutine drift_at(hh, amp, dr, st)
            type(hang_t), intent(in) :: hh
            real(dp), intent(in) :: amp
            real(dp), intent(out) :: dr
            type(status_t), intent(out) :: st
            real(dp) :: ad
            dr = 0.0_dp
            call problem_rig(prob, hh, prob%mass, prob%g, x, rg, st)
            if (st%code == STATUS_OK) call maxima_drift(rg, prob%acc, amp, DRIFT_CYCLES, dr, &
                                                        ad, st)
            if (st%code /= STATUS_OK) st%msg = hang_label(hh)//': '//st%msg
        end subroutine drift_at
        !> Two significant digits, rounded down.
        pure real(dp) function round2(v)
            real(dp), intent(in) :: v
            real(dp) :: e
            round2 = 0.0_dp
            if (.not. (v > 0.0_dp)) return
            e = 10.0_dp**(floor(log10(v)) - 1)
            round2 = floor(v/e)*e
        end function round2
    end subroutine amplitude_limits

    ! ------------------------------------------------------------------ the plan

    !> The period of a candidate hang at small amplitude and its sensitivities: to x (6),
    !! the three rotations, l, l_prime, b, b_prime, mass and g.
    subroutine candidate_row(prob, h, x, t, a, sdir, srig, smass, sg, stat)
        type(tensor_problem_t), intent(in) :: prob
        type(hang_t), intent(in) :: h
        real(dp), intent(in) :: x(6)
        real(dp), intent(out) :: t, a(6), sdir(3), srig(4), smass, sg
        type(status_t), intent(out) :: stat
        real(dp) :: xp(6), tp, tm, hh, eps(3), v
        type(hang_t) :: hp, hm
        integer :: k
        call case_period(prob, h, 0.0_dp, prob%mass, prob%g, x, t, stat)
        if (stat%code /= STATUS_OK) return
        hh = HX_LIN*maxval(x(1:3))
        do k = 1, 6
            xp = x
            xp(k) = x(k) + hh
            call case_period(prob, h, 0.0_dp, prob%mass, prob%g, xp, tp, stat)
            if (stat%code /= STATUS_OK) return
            xp(k) = x(k) - hh
            call case_period(prob, h, 0.0_dp, prob%mass, prob%g, xp, tm, stat)
            if (stat%code /= STATUS_OK) return
            a(k) = (tp - tm)/(2.0_dp*hh)
        end do
        do k = 1, 3
            eps = 0.0_dp
            eps(k) = HX_LIN
            call case_period(prob, turned_hang(h, eps), 0.0_dp, prob%mass, prob%g, x, tp, stat)
            if (stat%code /= STATUS_OK) return
            call case_period(prob, turned_hang(h, -eps), 0.0_dp, prob%mass, prob%g, x, tm, stat)
            if (stat%code /= STATUS_OK) return
            sdir(k) = (tp - tm)/(2.0_dp*HX_LIN)
        end do
        do k = 1, 4
            hp = h
            hm = h
            v = rig_value(h, k)
            call set_rig_value(hp, k, v*(1.0_dp + HX_LIN))
            call set_rig_value(hm, k, v*(1.0_dp - HX_LIN))
            call case_period(prob, hp, 0.0_dp, prob%mass, prob%g, x, tp, stat)
            if (stat%code /= STATUS_OK) return
            call case_period(prob, hm, 0.0_dp, prob%mass, prob%g, x, tm, stat)
            if (stat%code /= STATUS_OK) return
            srig(k) = (tp - tm)/(2.0_dp*HX_LIN*v)
        end do
        smass = -dot_product(x, a)/prob%mass
        if (prob%loaded) then
            ! a fixture or a mass centre off the table's: the model does not see J/m alone
            call case_period(prob, h, 0.0_dp, prob%mass*(1.0_dp + HX_LIN), prob%g, x, tp, stat)
            if (stat%code /= STATUS_OK) return
            call case_period(prob, h, 0.0_dp, prob%mass*(1.0_dp - HX_LIN), prob%g, x, tm, stat)
            if (stat%code /= STATUS_OK) return
            smass = (tp - tm)/(2.0_dp*HX_LIN*prob%mass)
        end if
        sg = -0.5_dp*t/prob%g
    end subroutine candidate_row

    !> The trace of the covariance of x for hangs with the given ups and alongs (body frame,
    !! unit, along normal to up) on the rig h0, at small amplitude, each with the timing u
    !! u_t (s, of its period: u_period over cycles, over the root of its timings), under
    !! prob's other uncertainties; also the periods and u of each entry.  Without any
    !! uncertainty of the period or the direction, each period counts 1e-4 of itself.
    subroutine design_trace(prob, h0, u_t, x, ups, alongs, trace, stat, periods, u_x)
        type(tensor_problem_t), intent(in) :: prob  !! mass, g, accuracy, uncertainties
        type(hang_t), intent(in) :: h0          !! the rig of every hang
        real(dp), intent(in) :: u_t             !! timing u of each period (s)
        real(dp), intent(in) :: x(6)            !! the tensor
        real(dp), intent(in) :: ups(:, :), alongs(:, :)  !! 3 x n
        real(dp), intent(out) :: trace
        type(status_t), intent(out) :: stat
        real(dp), intent(out), optional :: periods(:), u_x(:)
        real(dp), allocatable :: t(:), a(:, :), sdir(:, :), srig(:, :), smass(:), sg(:)
        real(dp) :: cc(6, 6)
        integer :: k, n
        type(hang_t) :: h
        n = size(ups, 2)
        allocate (t(n), a(n, 6), sdir(n, 3), srig(n, 4), smass(n), sg(n))
        do k = 1, n
            h = h0
            h%up = ups(:, k)
            h%along = alongs(:, k)
            call candidate_row(prob, h, x, t(k), a(k, :), sdir(k, :), srig(k, :), smass(k), &
                               sg(k), stat)
            if (stat%code /= STATUS_OK) return
        end do
        call set_covariance(prob, spread(u_t, 1, n), t, a, sdir, srig, smass, sg, &
                            [(k, k=1, n)], cc)
        trace = cc(1, 1) + cc(2, 2) + cc(3, 3) + cc(4, 4) + cc(5, 5) + cc(6, 6)
        if (present(periods)) periods = t
        if (present(u_x)) u_x = sqrt(max(0.0_dp, [(cc(k, k), k=1, 6)]))
    end subroutine design_trace

    !> The covariance of x from the candidate rows `set` (see design_trace); u_r: each
    !! candidate row's timing u (s).
    subroutine set_covariance(prob, u_r, t, a, sdir, srig, smass, sg, set, cc)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: u_r(:), t(:), a(:, :), sdir(:, :), srig(:, :), smass(:), sg(:)
        integer, intent(in) :: set(:)
        real(dp), intent(out) :: cc(6, 6)
        real(dp) :: nmat(6, 6), w(6), v(6, 6), ninv(6, 6), bk(6), sk(6), uc(6)
        real(dp) :: sens(size(t), 6)
        integer :: i, j, k
        type(status_t) :: st
        nmat = 0.0_dp
        do j = 1, size(set)
            i = set(j)
            nmat = nmat + outer(a(i, :), a(i, :))/row_var(i)
        end do
        cc = huge(1.0_dp)/1.0e10_dp
        call la_syev(nmat, w, v, st)
        if (st%code /= STATUS_OK) return
        if (.not. (w(1) > 1.0e-12_dp*w(6))) return
        ninv = 0.0_dp
        do k = 1, 6
            ninv = ninv + outer(v(:, k), v(:, k))/w(k)
        end do
        cc = ninv
        ! the common inputs: mass, g, l, l_prime, b, b_prime
        sens(:, 1) = smass
        sens(:, 2) = sg
        sens(:, 3:6) = srig
        uc = [prob%u%mass, prob%u%g, prob%u%rig]
        do k = 1, 6
            bk = 0.0_dp
            do j = 1, size(set)
                i = set(j)
                bk = bk + a(i, :)*sens(i, k)/row_var(i)
            end do
            sk = -matmul(ninv, bk)
            cc = cc + outer(sk, sk)*uc(k)**2
        end do
    contains
        pure real(dp) function row_var(ii)
            integer, intent(in) :: ii
            row_var = u_r(ii)**2 + sum(sdir(ii, :)**2)*prob%u%direction**2
            if (.not. (row_var > 0.0_dp)) row_var = (1.0e-4_dp*t(ii))**2
        end function row_var
    end subroutine set_covariance

    !> The attitude a planned hang would be measured with: -up turned into the plane of C,
    !! D and the mass centre of what hangs (where gravity lies at rest), unit.
    function planned_gravity(prob, h) result(gv)
        type(tensor_problem_t), intent(in) :: prob
        type(hang_t), intent(in) :: h
        real(dp) :: gv(3)
        real(dp) :: rf(3), jf(3, 3), gc(3), nrm(3)
        call fixture_in_body(h, prob%fix, prob%origin, rf, jf)
        gc = (prob%mass*prob%dcg + prob%fix%mass*rf)/(prob%mass + prob%fix%mass)
        nrm = plane_normal(h, gc)
        gv = -h%up - dot_product(-h%up, nrm)*nrm
        gv = gv/norm2(gv)
    end function planned_gravity

    !> The sensitivities that fitting the mass centre adds to candidate k (hang h, at small
    !! amplitude, the tensor x): dT/d(dcg) and, when its attitude is measured (att), the
    !! attitude residual's over dcg, the three rotations and the mass (central differences,
    !! the steps of cg_columns and attitude_sensitivities).
    subroutine cg_candidate(prob, h, x, att, k, cs, stat)
        type(tensor_problem_t), intent(in) :: prob
        type(hang_t), intent(in) :: h           !! its gravity set when att
        real(dp), intent(in) :: x(6)
        logical, intent(in) :: att
        integer, intent(in) :: k
        type(cg_sens_t), intent(inout) :: cs
        type(status_t), intent(out) :: stat
        type(tensor_problem_t) :: pp, pm
        real(dp) :: hc, tp, tm, eps(3)
        integer :: j
        hc = HX_LIN*h%b_prime
        cs%att(k) = att
        cs%r_cg(k, :) = 0.0_dp
        cs%r_dir(k, :) = 0.0_dp
        cs%r_mass(k) = 0.0_dp
        do j = 1, 3
            pp = prob
            pm = prob
            pp%dcg(j) = prob%dcg(j) + hc
            pm%dcg(j) = prob%dcg(j) - hc
            call case_period(pp, h, 0.0_dp, prob%mass, prob%g, x, tp, stat)
            if (stat%code == STATUS_OK) call case_period(pm, h, 0.0_dp, prob%mass, prob%g, &
                                                         x, tm, stat)
            if (stat%code /= STATUS_OK) return
            cs%t_cg(k, j) = (tp - tm)/(2.0_dp*hc)
            if (att) cs%r_cg(k, j) = (attitude_residual(pp, h, prob%mass) - &
                                      attitude_residual(pm, h, prob%mass))/(2.0_dp*hc)
        end do
        if (.not. att) return
        do j = 1, 3
            eps = 0.0_dp
            eps(j) = HX_LIN
            cs%r_dir(k, j) = (attitude_residual(prob, turned_hang(h, eps), prob%mass) - &
                attitude_residual(prob, turned_hang(h, -eps), prob%mass))/(2.0_dp*HX_LIN)
        end do
        cs%r_mass(k) = (attitude_residual(prob, h, prob%mass*(1.0_dp + HX_LIN)) - &
            attitude_residual(prob, h, prob%mass*(1.0_dp - HX_LIN)))/(2.0_dp*HX_LIN*prob%mass)
    end subroutine cg_candidate

    !> The joint covariance of (x, dcg) from the candidate rows `set` (the plan with the
    !! mass centre fitted): per hang its period row and, when its attitude is measured, its
    !! attitude row (u_attitude), the two sharing the hang's three rotations (u_direction);
    !! then the common inputs mass, g, l, l_prime, b, b_prime.  The normal matrix is
    !! inverted scaled by its diagonal (entries and lengths differ in units).
    subroutine joint_covariance(prob, u_r, t, a, sdir, srig, smass, sg, cs, set, cc)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: u_r(:), t(:), a(:, :), sdir(:, :), srig(:, :), smass(:), sg(:)
        type(cg_sens_t), intent(in) :: cs
        integer, intent(in) :: set(:)
        real(dp), intent(out) :: cc(9, 9)
        real(dp) :: nmat(9, 9), w(9), v(9, 9), ninv(9, 9), bk(9), sk(9), uc(6), sc(9)
        real(dp) :: jr(2, 9), vr(2, 2), wi(2, 2), sd(2, 3), det, sr(2)
        integer :: i, j, k, m
        type(status_t) :: st
        nmat = 0.0_dp
        do j = 1, size(set)
            i = set(j)
            call row_block(i)
            nmat = nmat + matmul(transpose(jr(1:m, :)), matmul(wi(1:m, 1:m), jr(1:m, :)))
        end do
        cc = huge(1.0_dp)/1.0e10_dp
        sc = [(sqrt(max(nmat(k, k), tiny(1.0_dp))), k=1, 9)]
        do k = 1, 9
            nmat(:, k) = nmat(:, k)/(sc*sc(k))
        end do
        call la_syev(nmat, w, v, st)
        if (st%code /= STATUS_OK) return
        if (.not. (w(1) > 1.0e-12_dp*w(9))) return
        ninv = 0.0_dp
        do k = 1, 9
            ninv = ninv + outer(v(:, k), v(:, k))/w(k)
        end do
        do k = 1, 9
            ninv(:, k) = ninv(:, k)/(sc*sc(k))
        end do
        cc = ninv
        uc = [prob%u%mass, prob%u%g, prob%u%rig]
        do k = 1, 6
            bk = 0.0_dp
            do j = 1, size(set)
                i = set(j)
                call row_block(i)
                select case (k)
                case (1)
                    sr = [smass(i), cs%r_mass(i)]
                case (2)
                    sr = [sg(i), 0.0_dp]
                case default
                    sr = [srig(i, max(k - 2, 1)), 0.0_dp]
                end select
                bk = bk + matmul(transpose(jr(1:m, :)), matmul(wi(1:m, 1:m), sr(1:m)))
            end do
            sk = -matmul(ninv, bk)
            cc = cc + outer(sk, sk)*uc(k)**2
        end do
    contains
        !> Candidate ii's rows: their Jacobian jr, covariance's inverse wi (m rows).
        subroutine row_block(ii)
            integer, intent(in) :: ii
            m = merge(2, 1, cs%att(ii))
            jr = 0.0_dp
            jr(1, 1:6) = a(ii, :)
            jr(1, 7:9) = cs%t_cg(ii, :)
            jr(2, 7:9) = cs%r_cg(ii, :)
            sd(1, :) = sdir(ii, :)
            sd(2, :) = cs%r_dir(ii, :)
            vr = matmul(sd, transpose(sd))*prob%u%direction**2
            vr(1, 1) = vr(1, 1) + u_r(ii)**2
            if (.not. (vr(1, 1) > 0.0_dp)) vr(1, 1) = (1.0e-4_dp*t(ii))**2
            vr(2, 2) = vr(2, 2) + prob%u%attitude**2
            if (.not. (vr(2, 2) > 0.0_dp)) m = 1
            if (m == 1) then
                wi(1, 1) = 1.0_dp/vr(1, 1)
            else
                det = vr(1, 1)*vr(2, 2) - vr(1, 2)*vr(2, 1)
                wi = reshape([vr(2, 2), -vr(2, 1), -vr(1, 2), vr(1, 1)], [2, 2])/det
            end if
        end subroutine row_block
    end subroutine joint_covariance

    !> n hangs among the 13 face, edge and corner directions of the body frame (u and -u
    !! one direction) that minimise the trace of the covariance of x (see the module
    !! header), on the rig h0, each with the timing u u_t; no direction is planned a second
    !! time before every one of the 13 is planned once (n > 13 takes all of them).  With
    !! `existing` (the table's hangs, each with its own timing u u_existing), the n hangs
    !! are added to them: the trace is the table's and the additions' together.  With the
    !! mass centre fitted (prob%est_cg) the problem is the fit's nine parameters, each
    !! planned hang with its attitude measured (u_attitude; a table's hang with it when
    !! the table gives it), and the trace minimised is the tensor's plus (m b')^2 times the
    !! mass centre's (m the mass, b' the rig's h0%b_prime: a shift d of the mass centre
    !! moves a moment about an axis b' away by about m b' d); plan%u_cg its u.
    subroutine plan_hangs(prob, h0, u_t, x, n, plan, stat, existing, u_existing)
        type(tensor_problem_t), intent(in) :: prob  !! mass, g, accuracy, uncertainties
        type(hang_t), intent(in) :: h0          !! the rig of every hang
        real(dp), intent(in) :: u_t             !! timing u of each period (s)
        real(dp), intent(in) :: x(6)            !! the tensor
        integer, intent(in) :: n                !! hangs, 1 .. 26
        type(tensor_plan_t), intent(out) :: plan
        type(status_t), intent(out) :: stat
        type(hang_t), intent(in), optional :: existing(:)   !! the table's hangs
        real(dp), intent(in), optional :: u_existing(:)     !! their timing u (s)
        integer, parameter :: NC = 13
        real(dp) :: c26(3, 26), c(3, NC), cc(6, 6), best, tr, c9(9, 9), wcg
        real(dp), allocatable :: t(:), a(:, :), sdir(:, :), srig(:, :), smass(:), sg(:), ur(:)
        integer, allocatable :: set(:), base(:)
        integer :: k, i, j, kb, it, ne
        logical :: improved
        type(hang_t) :: h
        type(cg_sens_t) :: cs
        c26 = candidate_directions()
        c = c26(:, 1:26:2)
        ne = 0
        if (present(existing)) ne = size(existing)
        allocate (t(NC + ne), a(NC + ne, 6), sdir(NC + ne, 3), srig(NC + ne, 4), &
                  smass(NC + ne), sg(NC + ne), ur(NC + ne))
        if (prob%est_cg) allocate (cs%t_cg(NC + ne, 3), cs%att(NC + ne), &
                                   cs%r_cg(NC + ne, 3), cs%r_dir(NC + ne, 3), cs%r_mass(NC + ne))
        wcg = (prob%mass*h0%b_prime)**2
        do k = 1, NC + ne
            h = h0
            h%up = c(:, min(k, NC))
            h%along = along_for(c(:, min(k, NC)))
            ur(k) = u_t
            if (k > NC) call table_hang(k - NC)
            call candidate_row(prob, h, x, t(k), a(k, :), sdir(k, :), srig(k, :), smass(k), &
                               sg(k), stat)
            if (stat%code == STATUS_OK .and. prob%est_cg) then
                if (k <= NC) then
                    h%attitude = .true.
                    h%gravity = planned_gravity(prob, h)
                end if
                call cg_candidate(prob, h, x, h%attitude, k, cs, stat)
            end if
            if (stat%code /= STATUS_OK) then
                stat%msg = 'the plan: '//stat%msg
                return
            end if
        end do
        base = [(NC + k, k=1, ne)]
        ! start: without a table the three faces and three edges (x, y, z, xy, xz, yz);
        ! then greedy
        if (ne == 0) then
            set = [1, 2, 3, first_of(1, 1, 0), first_of(1, 0, 1), first_of(0, 1, 1)]
            set = set(1:min(n, 6))
        else
            allocate (set(0))
        end if
        do while (size(set) < n)
            kb = 0
            best = huge(1.0_dp)
            do k = 1, NC
                if (.not. balanced([set, k])) cycle
                tr = trace_of([set, k])
                if (tr < best) then
                    best = tr
                    kb = k
                end if
            end do
            set = [set, kb]
        end do
        ! exchanges until none lowers the trace
        best = trace_of(set)
        do it = 1, 100
            improved = .false.
            do i = 1, size(set)
                do j = 1, NC
                    if (j == set(i)) cycle
                    k = set(i)
                    set(i) = j
                    if (.not. balanced(set)) then
                        set(i) = k
                        cycle
                    end if
                    tr = trace_of(set)
                    if (tr < best*(1.0_dp - 1.0e-12_dp)) then
                        best = tr
                        improved = .true.
                    else
                        set(i) = k
                    end if
                end do
            end do
            if (.not. improved) exit
        end do
        plan%n = n
        allocate (plan%up(3, n), plan%along(3, n), plan%period(n))
        do i = 1, n
            plan%up(:, i) = c(:, set(i))
            plan%along(:, i) = along_for(c(:, set(i)))
            plan%period(i) = t(set(i))
        end do
        plan%trace = best
        if (prob%est_cg) then
            call joint_covariance(prob, ur, t, a, sdir, srig, smass, sg, cs, [base, set], c9)
            plan%u_x = sqrt(max(0.0_dp, [(c9(k, k), k=1, 6)]))
            plan%u_cg = sqrt(max(0.0_dp, [(c9(k, k), k=7, 9)]))
        else
            call set_covariance(prob, ur, t, a, sdir, srig, smass, sg, [base, set], cc)
            plan%u_x = sqrt(max(0.0_dp, [(cc(k, k), k=1, 6)]))
        end if
    contains
        !> No direction planned twice before every one of the NC is planned once (and so
        !! on): the counts differ by at most 1.
        logical function balanced(s)
            integer, intent(in) :: s(:)
            integer :: cnt(NC), m
            cnt = [(count(s == m), m=1, NC)]
            balanced = maxval(cnt) - minval(cnt) <= 1
        end function balanced
        !> Candidate NC + e is the table's hang e.
        subroutine table_hang(e)
            integer, intent(in) :: e
            h = existing(e)
            ur(NC + e) = u_existing(e)
        end subroutine table_hang
        real(dp) function trace_of(s)
            integer, intent(in) :: s(:)
            real(dp) :: cv(6, 6), cw(9, 9)
            integer :: m
            if (prob%est_cg) then
                call joint_covariance(prob, ur, t, a, sdir, srig, smass, sg, cs, [base, s], cw)
                trace_of = sum([(cw(m, m), m=1, 6)]) + wcg*sum([(cw(m, m), m=7, 9)])
                return
            end if
            call set_covariance(prob, ur, t, a, sdir, srig, smass, sg, [base, s], cv)
            trace_of = sum([(cv(m, m), m=1, 6)])
        end function trace_of
        integer function first_of(i1, i2, i3)
            integer, intent(in) :: i1, i2, i3
            real(dp) :: v(3)
            integer :: m
            v = real([i1, i2, i3], dp)
            v = v/norm2(v)
            first_of = 1
            do m = 1, NC
                if (all(abs(c(:, m) - v) < 1.0e-12_dp)) then
                    first_of = m
                    return
                end if
            end do
        end function first_of
    end subroutine plan_hangs

    ! ------------------------------------------------------------------ Monte Carlo

    !> The amplitude part of each case's period and its first derivatives (the Monte
    !! Carlo's model, see the module header): D = T(x; hang, A) - T(x; hang, 0), the full
    !! model's period at the case's amplitude less the torsion mode's, and dD by central
    !! differences over x (6), the three rotations of the hang (per rad), its l, l_prime,
    !! b, b_prime (per unit) and the amplitude (per degree).  parts(:, c) = (D, dD/dx(6),
    !! dD/deps(3), dD/drig(4), dD/dA); zero for a case at amplitude 0.
    subroutine amplitude_parts(prob, x, parts, stat)
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: x(6)
        real(dp), intent(out) :: parts(:, :)    !! (MC_PARTS, cases)
        type(status_t), intent(out) :: stat
        type(hang_t) :: hp, hm
        real(dp) :: dp_, dm_, hx, hxx, ha, eps(3), xp(6), xm(6), v
        integer :: c, k
        parts = 0.0_dp
        stat%code = STATUS_OK
        hx = HX_SIM
        hxx = x_step(prob, x)
        do c = 1, size(prob%case_hang)
            associate (h => prob%hangs(prob%case_hang(c)), amp => prob%case_amp(c))
                if (.not. (amp > 0.0_dp)) cycle
                call part_d(h, amp, x, parts(1, c))
                if (stat%code /= STATUS_OK) return
                do k = 1, 6
                    xp = x
                    xm = x
                    xp(k) = x(k) + hxx
                    xm(k) = x(k) - hxx
                    call part_d(h, amp, xp, dp_)
                    if (stat%code == STATUS_OK) call part_d(h, amp, xm, dm_)
                    if (stat%code /= STATUS_OK) return
                    parts(1 + k, c) = (dp_ - dm_)/(2.0_dp*hxx)
                end do
                do k = 1, 3
                    eps = 0.0_dp
                    eps(k) = hx
                    call part_d(turned_hang(h, eps), amp, x, dp_)
                    if (stat%code == STATUS_OK) call part_d(turned_hang(h, -eps), amp, x, dm_)
                    if (stat%code /= STATUS_OK) return
                    parts(7 + k, c) = (dp_ - dm_)/(2.0_dp*hx)
                end do
                do k = 1, 4
                    hp = h
                    hm = h
                    v = rig_value(h, k)
                    call set_rig_value(hp, k, v*(1.0_dp + hx))
                    call set_rig_value(hm, k, v*(1.0_dp - hx))
                    call part_d(hp, amp, x, dp_)
                    if (stat%code == STATUS_OK) call part_d(hm, amp, x, dm_)
                    if (stat%code /= STATUS_OK) return
                    parts(10 + k, c) = (dp_ - dm_)/(2.0_dp*hx*v)
                end do
                ha = min(0.5_dp*amp, max(1.0e-3_dp, 1.0e-2_dp*amp))
                call part_d(h, amp + ha, x, dp_)
                if (stat%code == STATUS_OK) call part_d(h, amp - ha, x, dm_)
                if (stat%code /= STATUS_OK) return
                parts(15, c) = (dp_ - dm_)/(2.0_dp*ha)
            end associate
        end do
    contains
        subroutine part_d(hh, a, xx, d)
            type(hang_t), intent(in) :: hh
            real(dp), intent(in) :: a, xx(6)
            real(dp), intent(out) :: d
            real(dp) :: ts, t0
            d = 0.0_dp
            call case_period(prob, hh, a, prob%mass, prob%g, xx, ts, stat)
            if (stat%code == STATUS_OK) call case_period(prob, hh, 0.0_dp, prob%mass, &
                                                         prob%g, xx, t0, stat)
            if (stat%code == STATUS_OK) d = ts - t0
        end subroutine part_d
    end subroutine amplitude_parts

    !> The sections of a payload (mc_layout_t); with_cg: the mass centre's tail.
    pure function mc_layout(nh, n, nc, na, with_cg) result(lo)
        integer, intent(in) :: nh, n, nc, na
        logical, intent(in) :: with_cg
        type(mc_layout_t) :: lo
        lo%hangs = MC_HEAD_LEN
        lo%rows = lo%hangs + MC_HANG_LEN*nh
        lo%fit = lo%rows + MC_ROW_LEN*n
        lo%chord = lo%fit + MC_FIT_LEN
        lo%parts = lo%chord + 6*n
        lo%cg = lo%parts + 1 + MC_PARTS*nc
        lo%grav = lo%cg + MC_CG_LEN
        lo%cg_chord = lo%grav + MC_GRAV_LEN*nh
        lo%total = lo%cg
        if (with_cg) lo%total = lo%cg_chord + 9*(n + na)
    end function mc_layout

    !> What a tensor Monte Carlo needs beyond the deck, as reals (the sweep's payload): the
    !! seed, the counts, per hang its id, up, along, rig and mass centre, which rig inputs
    !! are its own, its cables (a platform: 3) and mass centre across, per row its hang,
    !! period, cycles, amplitude, timing u and u_def, the table's mass-centre origin, the
    !! estimate, its axes, its first-order u, the chord matrix (its first six rows and
    !! the rows' columns), the cases' amplitude parts; with the mass centre fitted a tail:
    !! the origin, dcg, its u, per hang its measured gravity and whether it has one, and the
    !! whole chord, 9 x (rows + attitudes).
    function tensor_mc_payload(prob, fit, seed, parts) result(p)
        type(tensor_problem_t), intent(in) :: prob
        type(tensor_fit_t), intent(in) :: fit
        integer, intent(in) :: seed
        real(dp), intent(in) :: parts(:, :)     !! (MC_PARTS, cases): amplitude_parts
        real(dp), allocatable :: p(:)
        integer :: h, i, k, own
        ! the sections in the order and of the lengths mc_layout_t names (MC_*_LEN)
        p = [real(seed, dp), real(size(prob%hangs), dp), real(size(prob%rows), dp)]
        do h = 1, size(prob%hangs)
            associate (hh => prob%hangs(h))
                own = 0
                do k = 1, 4
                    if (hh%own(k)) own = own + 2**(k - 1)
                end do
                p = [p, real(hh%id, dp), real(hh%line, dp), hh%up, hh%along, hh%l, &
                     hh%l_prime, hh%b, hh%b_prime, hh%cg_depth, hh%cg_offset, real(own, dp), &
                     real(hh%cables, dp), hh%cg_offset_y]
            end associate
        end do
        do i = 1, size(prob%rows)
            associate (r => prob%rows(i))
                p = [p, real(r%release, dp), real(r%line, dp), r%period, r%cycles, r%amplitude, &
                     fit%u_row(i), prob%u_def(i)]
            end associate
        end do
        p = [p, prob%origin, fit%x, reshape(fit%axes, [9]), fit%u_x, &
             reshape(fit%chord(1:6, 1:size(prob%rows)), [6*size(prob%rows)])]
        p = [p, real(size(parts, 2), dp), reshape(parts, [size(parts)])]
        if (prob%est_cg) then
            p = [p, prob%origin, fit%dcg, fit%u_dcg]
            do h = 1, size(prob%hangs)
                p = [p, prob%hangs(h)%gravity, merge(1.0_dp, 0.0_dp, prob%hangs(h)%attitude)]
            end do
            p = [p, reshape(fit%chord, [size(fit%chord)])]
        end if
    end function tensor_mc_payload

    !> The Monte Carlo task of a deck from its payload (tensor_mc_payload): the task rank 0
    !! runs and the other ranks of an MPI run build.  ERR_DECK when the payload is not one.
    subroutine tensor_mc_task(ten, sus, bod, acc, payload, task, stat)
        type(tensor_group_t), intent(in) :: ten         !! the deck's &tensor
        type(suspension_group_t), intent(in) :: sus     !! (g)
        type(body_group_t), intent(in) :: bod           !! (mass)
        type(accuracy_t), intent(in) :: acc             !! the deck's accuracy
        real(dp), intent(in) :: payload(:)
        type(tensor_mc_task_t), intent(out) :: task
        type(status_t), intent(out) :: stat
        type(measurement_t) :: set
        type(mc_layout_t) :: lo
        integer :: nh, n, h, i, j, k, own, nc, na
        logical :: cg
        stat%code = STATUS_OK
        if (size(payload) < 3) then
            call set_error(stat, ERR_DECK, 'tensor Monte Carlo: a payload too short')
            return
        end if
        task%seed = nint(payload(1))
        nh = nint(payload(2))
        n = nint(payload(3))
        cg = ten%estimates_cg()
        ! the count of cases, after the chord's six rows; then the measured attitudes
        lo = mc_layout(max(nh, 0), max(n, 0), 0, 0, .false.)
        nc = -1
        if (nh >= 1 .and. n >= 1 .and. size(payload) > lo%parts) nc = nint(payload(lo%parts + 1))
        na = 0
        if (nc >= 1) then
            lo = mc_layout(nh, n, nc, 0, cg)
            if (cg .and. size(payload) >= lo%cg_chord) na = count(payload(lo%grav + &
                MC_GRAV_LEN:lo%cg_chord:MC_GRAV_LEN) /= 0.0_dp)
            lo = mc_layout(nh, n, nc, na, cg)
        end if
        if (nh < 1 .or. n < 1 .or. nc < 1 .or. size(payload) /= lo%total) then
            call set_error(stat, ERR_DECK, 'tensor Monte Carlo: the payload does not match '// &
                'its counts')
            return
        end if
        allocate (set%releases(nh), set%obs(n))
        do h = 1, nh
            j = lo%hangs + MC_HANG_LEN*(h - 1)
            associate (hh => set%releases(h)%hang, q => payload(j + 1:j + MC_HANG_LEN))
                hh%id = nint(q(1))
                hh%line = nint(q(2))
                hh%up = q(3:5)
                hh%along = q(6:8)
                hh%l = q(9)
                hh%l_prime = q(10)
                hh%b = q(11)
                hh%b_prime = q(12)
                hh%cg_depth = q(13)
                hh%cg_offset = q(14)
                own = nint(q(15))
                do k = 1, 4
                    hh%own(k) = btest(own, k - 1)
                end do
                hh%cables = nint(q(16))
                hh%cg_offset_y = q(17)
                if (cg) then
                    j = lo%grav + MC_GRAV_LEN*(h - 1)
                    hh%gravity = payload(j + 1:j + 3)
                    hh%attitude = payload(j + 4) /= 0.0_dp
                end if
            end associate
        end do
        allocate (task%u_row(n))
        do i = 1, n
            j = lo%rows + MC_ROW_LEN*(i - 1)
            associate (r => set%obs(i), q => payload(j + 1:j + MC_ROW_LEN))
                r%kind = OBS_HANG
                r%release = nint(q(1))
                r%line = nint(q(2))
                r%period = q(3)
                r%cycles = q(4)
                r%amplitude = q(5)
                task%u_row(i) = q(6)
            end associate
        end do
        call problem_of(ten, sus, bod, acc, set, task%prob)
        task%prob%u_def = payload(lo%rows + MC_ROW_LEN:lo%fit:MC_ROW_LEN)
        j = lo%fit
        task%prob%origin = payload(j + 1:j + 3)
        task%x = payload(j + 4:j + 9)
        task%axes = reshape(payload(j + 10:j + 18), [3, 3])
        task%u_x = payload(j + 19:j + 24)
        task%chord = reshape(payload(lo%chord + 1:lo%parts), [6, n])
        task%parts = reshape(payload(lo%parts + 2:lo%cg), [MC_PARTS, nc])
        if (nc /= size(task%prob%case_hang)) then
            call set_error(stat, ERR_DECK, 'tensor Monte Carlo: the payload''s cases do not '// &
                'match its rows')
            return
        end if
        task%nest = MC_ESTIMATES - 3
        if (cg) then
            task%prob%origin = payload(lo%cg + 1:lo%cg + 3)
            task%dcg = payload(lo%cg + 4:lo%cg + 6)
            task%u_dcg = payload(lo%cg + 7:lo%cg + 9)
            task%prob%dcg = task%dcg
            task%chord = reshape(payload(lo%cg_chord + 1:lo%total), [9, n + na])
            task%nest = MC_ESTIMATES
        end if
    end subroutine tensor_mc_task

    !> Sample k of a tensor Monte Carlo (tensor_mc_sample).
    subroutine tensor_mc_point(self, k, est, stat)
        class(tensor_mc_task_t), intent(in) :: self
        integer, intent(in) :: k                !! sample number
        real(dp), intent(out) :: est(:)         !! MC_ESTIMATES
        type(status_t), intent(out) :: stat
        call tensor_mc_sample(self, k, est, stat)
    end subroutine tensor_mc_point

    !> Monte Carlo sample k (see the module header): est = x (6), the principal moments
    !! (3), the turns (rad) of axis 1 toward axes 2 and 3, of axis 2 toward 1 and 3, of
    !! axis 3 toward 1 and 2.
    subroutine tensor_mc_sample(task, k, est, stat)
        type(tensor_mc_task_t), intent(in) :: task
        integer, intent(in) :: k
        real(dp), intent(out) :: est(:)
        type(status_t), intent(out) :: stat
        type(tensor_problem_t) :: p
        type(rng_t) :: g
        real(dp) :: eps(3), z(4), x(6), w(3), v(3, 3), tol, a_new, ddm, ddg, u_all(9)
        real(dp), allocatable :: tc(:), tmeas(:), t0(:), fixed(:), epsh(:, :), drig(:, :)
        real(dp), allocatable :: aobs(:), res(:), dx(:)
        integer :: h, i, j, it, m, c, nh, n, na, np
        integer, parameter :: IK(6) = [1, 2, 3, 1, 1, 2], JK(6) = [1, 2, 3, 2, 3, 3]
        est = 0.0_dp
        g = rng_stream(task%seed, k)
        p = task%prob
        nh = size(p%hangs)
        n = size(p%rows)
        na = size(p%att_hang)
        np = size(task%chord, 1)
        allocate (epsh(3, nh), drig(4, nh), tmeas(n), fixed(n), t0(nh), tc(n), aobs(na), &
                  res(n + na), dx(np))
        drig = 0.0_dp
        p%mass = task%prob%mass + p%u%mass*rng_normal(g)
        p%g = task%prob%g + p%u%g*rng_normal(g)
        do j = 1, 4
            z(j) = rng_normal(g)
        end do
        do h = 1, nh
            do j = 1, 4
                if (p%hangs(h)%own(j)) cycle
                call set_rig_value(p%hangs(h), j, rig_value(p%hangs(h), j) + p%u%rig(j)*z(j))
                drig(j, h) = p%u%rig(j)*z(j)
            end do
        end do
        do h = 1, nh
            do j = 1, 3
                eps(j) = p%u%direction*rng_normal(g)
            end do
            p%hangs(h) = turned_hang(p%hangs(h), eps)
            epsh(:, h) = eps
            do j = 1, 4
                z(j) = rng_normal(g)
                if (.not. p%hangs(h)%own(j)) cycle
                call set_rig_value(p%hangs(h), j, rig_value(p%hangs(h), j) + p%u%rig(j)*z(j))
                drig(j, h) = p%u%rig(j)*z(j)
            end do
        end do
        ! per row: the timing, the amplitude, the definition drawn; the amplitude part of
        ! its period at the drawn inputs, to first order about the estimate's (the torsion
        ! mode's period, below, is exact)
        do i = 1, n
            tmeas(i) = p%rows(i)%period + task%u_row(i)*rng_normal(g)
            z(1) = rng_normal(g)
            a_new = p%rows(i)%amplitude
            if (a_new > 0.0_dp) a_new = max(0.0_dp, a_new + p%u%amplitude*z(1))
            tmeas(i) = tmeas(i) + sqrt(3.0_dp)*p%u_def(i)*(2.0_dp*rng_uniform(g) - 1.0_dp)
            c = task%prob%row_case(i)
            h = p%rows(i)%release
            associate (q => task%parts(:, c))
                ddm = -dot_product(task%x, q(2:7))/task%prob%mass
                ddg = -0.5_dp*q(1)/task%prob%g
                fixed(i) = q(1) + dot_product(q(8:10), epsh(:, h)) + &
                    dot_product(q(11:14), drig(:, h)) + &
                    q(15)*(a_new - p%rows(i)%amplitude) + ddm*(p%mass - task%prob%mass) + &
                    ddg*(p%g - task%prob%g)
            end associate
        end do
        ! the fixture, drawn last (its mass, mass centre, the six entries of its inertia);
        ! the torsion mode below sees it exactly, the amplitude parts keep the estimate's
        if (p%loaded) then
            p%fix%mass = max(0.0_dp, p%fix%mass + p%u%fix_mass*rng_normal(g))
            do j = 1, 3
                p%fix%cg(j) = p%fix%cg(j) + p%u%fix_cg(j)*rng_normal(g)
            end do
            do j = 1, 6
                z(1) = p%u%fix_inertia(j)*rng_normal(g)
                p%fix%inertia(IK(j), JK(j)) = p%fix%inertia(IK(j), JK(j)) + z(1)
                if (IK(j) /= JK(j)) p%fix%inertia(JK(j), IK(j)) = &
                    p%fix%inertia(JK(j), IK(j)) + z(1)
            end do
        end if
        ! with the mass centre fitted, each measured attitude last: its residual's reading
        ! (0 as measured) off by u_attitude
        do j = 1, na
            aobs(j) = p%u%attitude*rng_normal(g)
        end do
        x = task%x
        p%dcg = task%dcg
        u_all = [task%u_x, task%u_dcg]
        tol = X_TOL
        if (any(p%case_amp > 0.0_dp)) tol = max(X_TOL, 10.0_dp*p%acc%rtol)
        do it = 1, MAX_ITER
            do h = 1, nh
                call case_period(p, p%hangs(h), 0.0_dp, p%mass, p%g, x, t0(h), stat)
                if (stat%code /= STATUS_OK) exit
            end do
            if (stat%code /= STATUS_OK) exit
            do i = 1, n
                tc(i) = t0(p%rows(i)%release) + fixed(i) + &
                    dot_product(task%parts(2:7, task%prob%row_case(i)), x - task%x)
            end do
            res(1:n) = tc - tmeas
            do j = 1, na
                res(n + j) = attitude_residual(p, p%hangs(p%att_hang(j)), p%mass) - aobs(j)
            end do
            dx = -matmul(task%chord, res)
            x = x + dx(1:6)
            if (np > 6) p%dcg = p%dcg + dx(7:9)
            ! converged: at the model's resolution (the mass centre's step against the
            ! hangs' b_prime), or each step below 1e-3 of its u
            if (maxval(abs(dx(1:6))) <= 10.0_dp*tol*maxval(x(1:3))) then
                if (np == 6) exit
                if (maxval(abs(dx(7:9))) <= 10.0_dp*tol*p%hangs(1)%b_prime) exit
            end if
            if (all(u_all(1:np) > 0.0_dp) .and. all(abs(dx) <= MC_STEP*u_all(1:np))) exit
        end do
        if (stat%code == STATUS_OK .and. it > MAX_ITER) call set_error(stat, ERR_NUMERIC, &
            'the refit did not converge in '//itoa(MAX_ITER)//' steps')
        if (stat%code /= STATUS_OK) then
            stat%msg = 'Monte Carlo sample '//itoa(k)//': '//stat%msg
            if (p%u%direction > 0.0_dp) then
                stat%code = ERR_DECK
                stat%msg = '&tensor u_direction = '//rshort(p%u%direction/deg)//' deg: '// &
                    stat%msg//': hangs drawn this far from their directions leave the '// &
                    'region where the fit''s linearisation holds; allowed: a smaller '// &
                    'u_direction, or monte_carlo = 0 (the first-order u)'
            end if
            return
        end if
        call principal_axes(x, w, v, stat)
        if (stat%code /= STATUS_OK) return
        est(1:6) = x
        est(7:9) = w
        m = 9
        do i = 1, 3
            if (dot_product(v(:, i), task%axes(:, i)) < 0.0_dp) v(:, i) = -v(:, i)
            do j = 1, 3
                if (j == i) cycle
                m = m + 1
                est(m) = dot_product(v(:, i), task%axes(:, j))
            end do
        end do
        if (np > 6) est(16:18) = p%dcg
    end subroutine tensor_mc_sample

end module tensor_fit
