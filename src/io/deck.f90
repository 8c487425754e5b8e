!> The input deck: a namelist file with the groups &scene, &suspension, &body, &start,
!! &integration, &cables, &floquet, &chart, &design, &output, &damping and &measurement
!! (see input/*.nml and doc/deck.md).
!!
!! read_deck reads the file once into memory (deck_t%text, which also travels to the other
!! ranks of an MPI run: read_deck_text); each group is then read by its read_<group> from
!! its own text and checked by its check_<group>.  Every problem is an ERR_DECK status whose
!! message names the deck, the group, the variable and its value, what is wrong and what is
!! allowed.  Cable reachability is checked by the rig layer (module rig).
!!
!! The module and its two submodules:
!! - deck (this file): the type, the constants, reading (read_<group>) and the echo;
!! - deck_checks: check_<group>, the values of each group in range;
!! - deck_diagnose: the file's lines (group names, long lines) and the explanation of a
!!   namelist read error, with its own tokenizer.
module deck
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, rshort, rlist_short, lower, next_word, commas, clip, quoted
    use lines, only: read_line, LINE_MAX
    use fptraps, only: traps_off, traps_restore, NTRAPS
    implicit none
    private

    !> The columns of a simulation's .dat file, in their order (&output columns picks some).
    character(len=*), parameter, public :: OUTPUT_COLUMNS = 'tau theta1 theta2 theta3 '// &
        'theta4 theta5 theta1_dot theta2_dot theta3_dot theta4_dot theta5_dot Q Q_axis T_BC '// &
        'T_AD energy_error constraint_residual'
    !> Most periods in &measurement periods (and amplitudes).
    integer, parameter, public :: MAX_PERIODS = 100
    !> The value of an element of periods, amplitudes the deck did not give.
    real(dp), parameter, public :: PERIOD_UNSET = -huge(1.0_dp)
    !> Words allowed in &measurement estimate: the parameters a record fit can estimate.
    character(len=*), parameter, public :: ESTIMATES_ALLOWED = 'I1 c_v c_q amplitude t0 bias'
    !> Words allowed in &measurement record_units (each implies the quantity).
    character(len=*), parameter, public :: RECORD_UNITS_ALLOWED = 'rad deg rad/s deg/s'
    !> Words allowed in &measurement loss.
    character(len=*), parameter, public :: LOSSES_ALLOWED = 'squares huber'
    !> Words allowed in &measurement quantity: column 2 of a record.
    character(len=*), parameter, public :: QUANTITIES_ALLOWED = 'angle rate'

    type, public :: deck_t
        character(len=:), allocatable :: path        !! deck file as given
        character(len=:), allocatable :: name        !! file name without directory and .nml
        character(len=:), allocatable :: text        !! the deck file's lines, joined by newlines
        ! &scene
        character(len=256) :: title = ''
        character(len=256) :: analyses = 'simulate'
        character(len=256) :: model = 'kane'          !! MODELS_ALLOWED: 'kane' or 'elastic'
        !> the physical inputs the deck gave itself (' g mass l ... '; see GIVEN_TRACKED): a
        !! deck that measures must give them, the paper's decks keep the defaults
        character(len=:), allocatable :: given
        ! &suspension (lengths in any one unit; b and b_prime the full distances between the
        ! two cables on the support and on the body)
        real(dp) :: b = 1.0_dp, b_prime = 1.0_dp, l = 2.0_dp, l_prime = 2.0_dp, g = 1.0_dp
        !> cables >= 3: a platform of that many cables at radius on the support and
        !! radius_prime on the body (analysis identify; its torsion is that of b = 2 radius,
        !! b_prime = 2 radius_prime)
        integer :: cables = 2
        real(dp) :: radius = 0.0_dp, radius_prime = 0.0_dp
        ! &body
        real(dp) :: mass = 1.0_dp
        real(dp) :: inertia(3) = [0.125_dp, 0.1458333333333333_dp, 0.1458333333333333_dp]
        !> the mass centre from C (eq. (21)): r and lambda, or as measured: its depth below the
        !! line CD (cg_depth) and its offset along CD from the midpoint of CD, toward D
        !! (cg_offset); r cos(lambda) = b_prime/2 + cg_offset, r sin(lambda) = cg_depth
        real(dp) :: r = 0.7071067811865476_dp, lambda = 0.7853981633974483_dp
        real(dp) :: cg_depth = 0.0_dp, cg_offset = 0.0_dp
        !> default identity; btilde(i,:) is row i as printed in the paper
        real(dp) :: btilde(3,3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                           0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
        real(dp) :: sway_depth = 1.0_dp
        ! &start
        character(len=256) :: mode = 'raised'
        real(dp) :: amplitude = 45.0_dp, tilt = 0.0_dp     !! degrees, radians
        real(dp) :: theta(4) = 0.0_dp, theta_dot(4) = 0.0_dp
        ! &integration
        real(dp) :: tau_end = 60.0_dp, dtau_out = 0.05_dp, rtol = 1.0e-10_dp, atol = 1.0e-12_dp
        logical  :: error_estimate = .false.
        character(len=256) :: method = 'auto'      !! METHODS_ALLOWED: the integrator
        !> SENSITIVITIES_ALLOWED: derivatives of whole runs by forward sensitivities or by
        !! the paths of before (differences of runs; Floquet's augmented system)
        character(len=256) :: sensitivities = 'forward'
        !> .true.: forward sensitivities take part in the integrator's error test (a record
        !! fit's Jacobian and budget; Floquet's monodromy always does)
        logical :: sensitivity_error_control = .false.
        ! &cables (model = 'elastic' only)
        real(dp) :: cable_stiffness = 1.0e6_dp    !! EA/(m g) of each cable, 1 <= k <= 1e12
        real(dp) :: cable_damping = 0.05_dp       !! damping ratio zeta of each cable, 0..10
        ! &floquet
        real(dp) :: floquet_amplitude = 45.0_dp   !! degrees of theta4, 0 < a < 180
        integer  :: floquet_segments = 1          !! shooting segments, 1..64
        real(dp) :: floquet_rtol = 1.0e-10_dp     !! 1e-14 <= rtol < 1e-2
        ! &chart (axis variables: see CHART_VARIABLES)
        character(len=256) :: chart_x = 'l', chart_y = 'amplitude'
        real(dp) :: chart_x_min = 0.5_dp, chart_x_max = 4.0_dp
        real(dp) :: chart_y_min = 5.0_dp, chart_y_max = 90.0_dp
        integer  :: chart_nx = 40, chart_ny = 40
        ! &output: the .dat columns, blank-separated names of OUTPUT_COLUMNS in their order
        character(len=512) :: columns = OUTPUT_COLUMNS
        ! &design (analysis design): candidate rigs l = l' (and b) and the instruments'
        ! standard uncertainties, all in deck units (period in s); checked only when the
        ! analysis is requested (see check_design)
        real(dp) :: design_l_min = 0.4_dp, design_l_max = 3.0_dp
        integer  :: design_nl = 60
        real(dp) :: design_b_min = 0.0_dp, design_b_max = 0.0_dp  !! 0, 0 with nb = 1: deck's b
        integer  :: design_nb = 1
        !> the body's spacing b' (0, 0 with nb_prime = 1: the deck's b')
        real(dp) :: design_b_prime_min = 0.0_dp, design_b_prime_max = 0.0_dp
        integer  :: design_nb_prime = 1
        real(dp) :: design_amplitude_max = 50.0_dp  !! degrees, 0 < a <= 90
        !> the amplitude (degrees) at which the precision is predicted; PERIOD_UNSET: not
        !! given, then min(25, amplitude_max) (check_design)
        real(dp) :: design_amplitude_measure = PERIOD_UNSET
        integer  :: design_n_amplitudes = 6
        real(dp) :: design_u_mass = 1.0e-3_dp, design_u_l = 1.0e-3_dp
        real(dp) :: design_u_b = 5.0e-4_dp, design_u_period = 1.0e-4_dp
        ! &damping: a torque on the body about the vertical, M = -(c_v W + c_q |W| W) n3,
        ! W = omega . n3 (used by the paper's model: simulate, identify)
        real(dp) :: c_v = 0.0_dp                  !! torque per angular rate (deck units, >= 0)
        real(dp) :: c_q = 0.0_dp                  !! torque per rate squared (deck units, >= 0)
        ! &measurement (analysis identify): measured periods or a recorded swing
        integer :: n_periods = 0                  !! periods given (periods(1:n_periods))
        real(dp) :: periods(MAX_PERIODS) = PERIOD_UNSET     !! full periods (s)
        real(dp) :: amplitudes(MAX_PERIODS) = PERIOD_UNSET  !! their peak theta4 (degrees)
        character(len=256) :: record = ''         !! record file as given ('' for none)
        character(len=:), allocatable :: record_path  !! the record relative to the deck's folder
        character(len=256) :: quantity = 'angle'  !! QUANTITIES_ALLOWED: column 2 of the record
        character(len=256) :: estimate = 'I1'     !! ESTIMATES_ALLOWED: the parameters fitted
        !> standard uncertainties (deck units; period in s, amplitude in degrees), >= 0
        real(dp) :: u_mass = 0.0_dp, u_l = 0.0_dp, u_l_prime = 0.0_dp, u_b = 0.0_dp
        real(dp) :: u_b_prime = 0.0_dp, u_g = 0.0_dp, u_period = 0.0_dp, u_amplitude = 0.0_dp
        integer :: monte_carlo = 0                !! Monte Carlo samples (0: first order only)
        integer :: seed = 1                       !! seed of the Monte Carlo streams
        !> each period is the total time of cycles(i) cycles (PERIOD_UNSET: 1); one value
        !! serves every period
        real(dp) :: cycles(MAX_PERIODS) = PERIOD_UNSET
        character(len=256) :: trials = ''         !! a table of releases ('' for none)
        character(len=:), allocatable :: trials_path  !! relative to the deck's folder
        !> the record's columns: time, value and (0: none) each sample's u; -1 in the third:
        !! not given, then column 3 when the record has exactly three columns (else none)
        integer :: record_columns(3) = [1, 2, -1]
        character(len=256) :: record_units = ''   !! RECORD_UNITS_ALLOWED ('' : by quantity)
        character(len=256) :: loss = 'squares'    !! LOSSES_ALLOWED: the record fit's loss
        !> standard uncertainties of I2 and I3, of the mass centre (as measured: cg_depth,
        !! cg_offset; or r (length) and lambda (rad))
        real(dp) :: u_inertia(2) = 0.0_dp
        real(dp) :: u_cg_depth = 0.0_dp, u_cg_offset = 0.0_dp, u_r = 0.0_dp, u_lambda = 0.0_dp
        !> a fixture measured alone and subtracted (its I1 about the same axis, u, its mass),
        !! and a known added inertia (e.g. entrained air) subtracted
        real(dp) :: tare_i1 = 0.0_dp, u_tare_i1 = 0.0_dp, tare_mass = 0.0_dp
        real(dp) :: added_inertia = 0.0_dp, u_added_inertia = 0.0_dp
        ! &tensor (analysis tensor): the table of hangs and the uncertainties of its inputs
        character(len=256) :: tensor_hangs = ''   !! the hangs table as given ('' for none)
        character(len=:), allocatable :: tensor_hangs_path  !! relative to the deck's folder
        !> standard uncertainties of mass, l, l_prime, b, b_prime, g, period (s), amplitude
        !! (degrees), deck units
        real(dp) :: tensor_u(8) = 0.0_dp
        real(dp) :: tensor_u_direction = 0.0_dp   !! of how the body was set in a hang (deg)
        integer :: tensor_monte_carlo = 0, tensor_seed = 1
        real(dp) :: tensor_cg(3) = 0.0_dp         !! the mass centre in the body frame
        logical :: tensor_cg_given = .false.
        integer :: tensor_plan = 0                !! hangs to plan (0: none)
    end type deck_t

    public :: read_deck, read_deck_text, analysis_requested, deck_echo, estimated, deck_gave
    public :: record_in_folder

    !> The physical inputs whose presence in the deck is recorded (deck_t%given).
    character(len=*), parameter :: GIVEN_TRACKED = 'g mass l l_prime b b_prime r lambda '// &
        'cg_depth cg_offset cables radius radius_prime inertia'
    !> The value a tracked input has before the namelist read: still there after it, the
    !! deck did not give the input.
    real(dp), parameter :: NOT_GIVEN = -huge(1.0_dp)
    !> Most cables of a platform (&suspension cables).
    integer, parameter :: MAX_CABLES = 12

    !> Words allowed in &scene analyses.
    character(len=*), parameter :: ANALYSES_ALLOWED = &
        'simulate floquet chart work_precision design identify tensor'
    !> Namelist groups a deck may contain.
    character(len=*), parameter :: GROUPS_ALLOWED = 'scene suspension body start '// &
        'integration cables floquet chart output design damping measurement tensor'
    !> Words allowed in &scene model.
    character(len=*), parameter :: MODELS_ALLOWED = 'kane elastic'
    !> Words allowed in &integration method: 'auto' (radau for model = 'elastic', lsoda for
    !! the paper's model), 'lsoda', 'radau'.
    character(len=*), parameter :: METHODS_ALLOWED = 'auto lsoda radau'
    !> Words allowed in &integration sensitivities: 'forward' (sensitivities integrated with
    !! the state), 'differences' (differences of whole runs, and Floquet's monodromy
    !! integrated as one system with the orbit).
    character(len=*), parameter :: SENSITIVITIES_ALLOWED = 'forward differences'
    !> Words allowed in &chart x and y.
    character(len=*), parameter :: CHART_VARIABLES = 'l b amplitude r lambda inertia_ratio'
    !> Variables of each group with their kind (r real, i integer, c character, l logical)
    !! and size; used only to explain a namelist read error.
    character(len=*), parameter :: SPEC_SCENE = 'title:c1 analyses:c1 model:c1'
    character(len=*), parameter :: SPEC_SUSPENSION = 'b:r1 b_prime:r1 l:r1 l_prime:r1 g:r1 '// &
        'cables:i1 radius:r1 radius_prime:r1'
    character(len=*), parameter :: SPEC_BODY = &
        'mass:r1 inertia:r3 r:r1 lambda:r1 cg_depth:r1 cg_offset:r1 btilde:r9 sway_depth:r1'
    character(len=*), parameter :: SPEC_START = 'mode:c1 amplitude:r1 tilt:r1 theta:r4 theta_dot:r4'
    character(len=*), parameter :: SPEC_INTEGRATION = &
        'tau_end:r1 dtau_out:r1 rtol:r1 atol:r1 error_estimate:l1 method:c1 sensitivities:c1 '// &
        'sensitivity_error_control:l1'
    character(len=*), parameter :: SPEC_CABLES = 'stiffness:r1 damping:r1'
    character(len=*), parameter :: SPEC_FLOQUET = 'amplitude:r1 segments:i1 rtol:r1'
    character(len=*), parameter :: SPEC_CHART = &
        'x:c1 x_min:r1 x_max:r1 nx:i1 y:c1 y_min:r1 y_max:r1 ny:i1'
    character(len=*), parameter :: SPEC_OUTPUT = 'columns:c1'
    character(len=*), parameter :: SPEC_DESIGN = 'l_min:r1 l_max:r1 nl:i1 b_min:r1 b_max:r1 '// &
        'nb:i1 amplitude_max:r1 n_amplitudes:i1 u_mass:r1 u_l:r1 u_b:r1 u_period:r1 '// &
        'b_prime_min:r1 b_prime_max:r1 nb_prime:i1 amplitude_measure:r1'
    character(len=*), parameter :: SPEC_DAMPING = 'c_v:r1 c_q:r1'
    character(len=*), parameter :: SPEC_MEASUREMENT = 'periods:r100 amplitudes:r100 '// &
        'record:c1 quantity:c1 estimate:c1 u_mass:r1 u_l:r1 u_l_prime:r1 u_b:r1 '// &
        'u_b_prime:r1 u_g:r1 u_period:r1 u_amplitude:r1 monte_carlo:i1 seed:i1 cycles:r100 '// &
        'trials:c1 record_columns:i3 record_units:c1 loss:c1 u_inertia:r2 u_cg_depth:r1 '// &
        'u_cg_offset:r1 u_r:r1 u_lambda:r1 tare_i1:r1 u_tare_i1:r1 tare_mass:r1 '// &
        'added_inertia:r1 u_added_inertia:r1'
    character(len=*), parameter :: SPEC_TENSOR = 'hangs:c1 u_mass:r1 u_l:r1 u_l_prime:r1 '// &
        'u_b:r1 u_b_prime:r1 u_g:r1 u_period:r1 u_amplitude:r1 u_direction:r1 '// &
        'monte_carlo:i1 seed:i1 cg:r3 plan:i1'
    !> Most Monte Carlo samples of &measurement monte_carlo.
    integer, parameter :: MAX_MONTE_CARLO = 1000000
    !> Largest damping coefficient in the scaled units of the model (c_v over
    !! m b' sqrt(g b'), c_q over m b'^2; critical damping of torsion is of order 1).
    real(dp), parameter :: DAMPING_SCALED_MAX = 1.0e3_dp
    real(dp), parameter :: RTOL_MIN = 1.0e-14_dp        !! smallest relative tolerance
    real(dp), parameter :: ATOL_MIN = 1.0e-30_dp        !! smallest absolute tolerance
    real(dp), parameter :: ATOL_MAX = 1.0_dp            !! largest absolute tolerance
    real(dp), parameter :: MAX_ROWS = 1.0e5_dp          !! largest tau_end/dtau_out
    real(dp), parameter, public :: TAU_END_MAX = 1.0e6_dp   !! longest simulation (units of tau)
    !> Every dimensional value (lengths, g, mass, moments of inertia) lies in
    !! DIM_MIN .. DIM_MAX, in any units: no product of them over- or underflows.
    real(dp), parameter :: DIM_MIN = 1.0e-100_dp, DIM_MAX = 1.0e100_dp
    !> The scale-free ratios: b, l, l' over b' in RATIO_MIN .. RATIO_MAX; r and |sway_depth|
    !! over b' at most RATIO_MAX; each principal moment over m b'^2 in INERTIA_MIN ..
    !! INERTIA_MAX.
    real(dp), parameter :: RATIO_MIN = 1.0e-3_dp, RATIO_MAX = 1.0e3_dp
    real(dp), parameter :: INERTIA_MIN = 1.0e-6_dp, INERTIA_MAX = 1.0e6_dp
    !> Largest |angle| (rad) of tilt, theta, lambda; angles are reduced modulo 2 pi.
    real(dp), parameter :: ANGLE_MAX = 1.0e6_dp
    !> Largest |theta_dot| (rad per unit tau); the natural frequencies are of order 1.
    real(dp), parameter :: RATE_MAX = 1.0e3_dp
    real(dp), parameter :: STIFFNESS_MIN = 1.0_dp       !! &cables stiffness range
    real(dp), parameter :: STIFFNESS_MAX = 1.0e12_dp
    real(dp), parameter :: DAMPING_MAX = 10.0_dp        !! largest &cables damping ratio
    real(dp), parameter :: ORTHO_TOL = 1.0e-9_dp        !! orthonormality of btilde
    real(dp), parameter :: TRIANGLE_SLACK = 1.0e-12_dp  !! relative slack of I1 <= I2 + I3
    real(dp), parameter :: FLOQUET_RTOL_MAX = 1.0e-2_dp !! largest &floquet rtol (excluded)
    integer, parameter :: MAX_SEGMENTS = 64             !! most &floquet shooting segments
    integer, parameter :: MAX_CHART_N = 1000            !! most chart points along one axis
    integer, parameter :: MAX_CHART_POINTS = 250000     !! most chart points, nx*ny
    integer, parameter :: MAX_DESIGN_AMPLITUDES = 100   !! most &design n_amplitudes
    !> Smallest torsion amplitude of a Floquet analysis (degrees; &floquet, a chart's
    !! amplitude axis, the design's smallest amplitude): the linear limit is reached long
    !! before, and below about 1e-170 degrees products in the variational analysis underflow.
    real(dp), parameter :: FLOQUET_AMPLITUDE_MIN = 1.0e-6_dp
    real(dp), parameter :: PI_HALF = 1.5707963267948966_dp
    integer, parameter :: MAX_LINE = LINE_MAX           !! longest deck line (characters)
    integer, parameter :: MAX_DECK_BYTES = 1000000      !! largest deck (bytes)
    integer, parameter :: MAX_TEXT = 256                !! longest quoted value (title, words)

    !> One line of the deck in memory (tabs and carriage returns as blanks).
    type, public :: deck_line_t
        character(len=:), allocatable :: s
    end type deck_line_t

    ! ---- submodule deck_checks: the values of each group
    interface
        !> &scene: model and analyses known words (normalised to lower case).
        module subroutine check_scene(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_scene
        !> &suspension: lengths and g finite, > 0, in range; a platform of 3 or more cables
        !! as its equivalent pair (b = 2 radius, b_prime = 2 radius_prime).
        module subroutine check_suspension(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_suspension
        !> &body: mass, principal moments, mass centre (cg_depth, cg_offset as r, lambda),
        !! btilde.
        module subroutine check_body(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_body
        !> &start: mode, amplitude, angles and rates.
        module subroutine check_start(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_start
        !> &integration: method, span, output step, tolerances.
        module subroutine check_integration(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_integration
        !> &cables: stiffness and damping ratio.
        module subroutine check_cables(d, stat)
            type(deck_t), intent(in) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_cables
        !> &floquet: amplitude, segments, rtol.
        module subroutine check_floquet(d, stat)
            type(deck_t), intent(in) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_floquet
        !> &chart: the two axes.
        module subroutine check_chart(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_chart
        !> &output: the .dat columns.
        module subroutine check_output(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_output
        !> &design (when the analysis is requested): the candidate grid and uncertainties;
        !! amplitude_measure defaults to min(25, amplitude_max).
        module subroutine check_design(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_design
        !> &damping: c_v, c_q.
        module subroutine check_damping(d, stat)
            type(deck_t), intent(in) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_damping
        !> &tensor: the uncertainties, Monte Carlo, the plan, a table of hangs when asked.
        module subroutine check_tensor(d, stat)
            type(deck_t), intent(in) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_tensor
        !> &measurement: periods, amplitudes, record, uncertainties, Monte Carlo.
        module subroutine check_measurement(d, stat)
            type(deck_t), intent(inout) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_measurement
        !> A deck that measures (identify, tensor, design) gives every physical input itself;
        !! a platform of 3 or more cables only with identify.
        module subroutine check_measuring(d, stat)
            type(deck_t), intent(in) :: d
            type(status_t), intent(inout) :: stat
        end subroutine check_measuring
        !> The deck's angles reduced modulo 2 pi.
        module subroutine reduce_angles(d)
            type(deck_t), intent(inout) :: d
        end subroutine reduce_angles
    end interface

    ! ---- submodule deck_diagnose: the lines and the explanation of read errors
    interface
        !> Every '&name' that starts a group is a known group; `seen` lists them.
        module subroutine check_group_names(lines, stat, seen)
            type(deck_line_t), intent(in) :: lines(:)
            type(status_t), intent(inout) :: stat
            character(len=:), allocatable, intent(out) :: seen
        end subroutine check_group_names
        !> The first '&grp' outside comments: its items, its line ends, and the group as one
        !! record for the namelist reader.
        module subroutine scan_group(lines, grp, found, complete, text, breaks, rec)
            type(deck_line_t), intent(in) :: lines(:)
            character(len=*), intent(in) :: grp
            logical, intent(out) :: found, complete
            character(len=:), allocatable, intent(out) :: text, rec
            integer, allocatable, intent(out) :: breaks(:)
        end subroutine scan_group
        !> A value longer than MAX_TEXT characters ('' when none).
        module function long_text(text) result(why)
            character(len=*), intent(in) :: text
            character(len=:), allocatable :: why
        end function long_text
        !> The first parenthesis the run-time library cannot be trusted with ('' when none).
        module function subscript_problem(text, breaks) result(why)
            character(len=*), intent(in) :: text
            integer, intent(in) :: breaks(:)
            character(len=:), allocatable :: why
        end function subscript_problem
        !> Why the run-time library could not read a group ('' when not found).
        !> A namelist error as 'WHAT NOTE; allowed: ...': the allowed part of what when it
        !! has one (moved after the note), else the group's variables (spec, see SPEC_*).
        module function with_allowed(what, note, spec) result(m)
            character(len=*), intent(in) :: what, note, spec
            character(len=:), allocatable :: m
        end function with_allowed

        module function explain(text, grp, spec) result(why)
            character(len=*), intent(in) :: text, grp, spec
            character(len=:), allocatable :: why
        end function explain
    end interface

contains

    !> Read and validate the deck at `path` into d: the file is read once (its size, every
    !! line's length), then parsed (read_deck_text's work).  Absent optional groups keep
    !! defaults; &suspension and &body are required.
    subroutine read_deck(path, d, stat)
        character(len=*), intent(in) :: path        !! deck file
        type(deck_t), intent(out) :: d              !! the effective deck (defaults + file)
        type(status_t), intent(out) :: stat         !! ERR_DECK with a message on any problem
        type(deck_line_t), allocatable :: ls(:)
        call load_lines(path, ls, stat)
        if (stat%code /= STATUS_OK) return
        call parse_deck(path, ls, d, stat)
    end subroutine read_deck

    !> As read_deck, from the deck's text already in memory (deck_t%text of the same deck
    !! read elsewhere, e.g. on rank 0 of an MPI run): the same checks, the same deck.
    subroutine read_deck_text(path, text, d, stat)
        character(len=*), intent(in) :: path        !! the deck as given (names, messages)
        character(len=*), intent(in) :: text        !! its lines joined by newlines
        type(deck_t), intent(out) :: d
        type(status_t), intent(out) :: stat
        type(deck_line_t), allocatable :: ls(:)
        integer :: n, i, i0
        stat%code = STATUS_OK
        n = count([(text(i:i) == achar(10), i = 1, len(text))]) + 1
        allocate (ls(n))
        i0 = 1
        n = 0
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= achar(10)) cycle
            end if
            n = n + 1
            ls(n)%s = text(i0:i - 1)
            i0 = i + 1
        end do
        if (len(text) == 0) n = 0
        call parse_deck(path, ls(1:n), d, stat)
    end subroutine read_deck_text

    !> The deck file's lines, read once: a file larger than MAX_DECK_BYTES, a line longer than
    !! MAX_LINE characters or a file that cannot be read is refused.
    subroutine load_lines(path, ls, stat)
        character(len=*), intent(in) :: path        !! deck file
        type(deck_line_t), allocatable, intent(out) :: ls(:)
        type(status_t), intent(inout) :: stat       !! ERR_DECK
        type(deck_line_t), allocatable :: grown(:)
        character(len=:), allocatable :: line
        character(len=512) :: msg
        integer :: u, ios, n
        integer(int64) :: fsize, nbytes
        msg = ''
        inquire (file=path, size=fsize, iostat=ios)
        if (ios == 0 .and. fsize > MAX_DECK_BYTES) then
            call set_error(stat, ERR_DECK, 'the deck is larger than '//itoa(MAX_DECK_BYTES)// &
                           ' bytes; allowed: decks of at most '//itoa(MAX_DECK_BYTES)//' bytes')
            return
        end if
        open (newunit=u, file=path, status='old', action='read', form='formatted', &
              access='sequential', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, 'cannot open the deck: '//trim(msg)//'; allowed: '// &
                           'a readable text file of namelist groups')
            return
        end if
        allocate (ls(64))
        n = 0
        nbytes = 0
        do
            call read_line(u, line, ios, msg)
            if (ios > 0) then
                call set_error(stat, ERR_DECK, 'cannot read the deck: '//trim(msg)// &
                               '; allowed: a readable text file of namelist groups')
                exit
            end if
            if (ios < 0) exit
            n = n + 1
            nbytes = nbytes + len(line) + 1
            if (len(line) > MAX_LINE) then
                call set_error(stat, ERR_DECK, 'line '//itoa(n)//' is longer than '// &
                               itoa(MAX_LINE)//' characters; allowed: lines of at most '// &
                               itoa(MAX_LINE)//' characters (a title holds 256)')
                exit
            end if
            if (nbytes > MAX_DECK_BYTES) then
                call set_error(stat, ERR_DECK, 'the deck is larger than '// &
                               itoa(MAX_DECK_BYTES)//' bytes; allowed: decks of at most '// &
                               itoa(MAX_DECK_BYTES)//' bytes')
                exit
            end if
            if (n > size(ls)) then
                allocate (grown(2*size(ls)))
                grown(1:n - 1) = ls(1:n - 1)
                call move_alloc(grown, ls)
            end if
            call move_alloc(line, ls(n)%s)
        end do
        close (u, iostat=ios)
        if (stat%code /= STATUS_OK) return
        ls = ls(1:n)
    end subroutine load_lines

    !> Parse a deck's lines into d: the group names, each group read (read_<group>), then
    !! each group checked (check_<group>).
    subroutine parse_deck(path, ls, d, stat)
        character(len=*), intent(in) :: path        !! the deck as given
        type(deck_line_t), intent(in) :: ls(:)      !! its lines
        type(deck_t), intent(out) :: d
        type(status_t), intent(inout) :: stat
        character(len=:), allocatable :: seen
        logical :: halting(NTRAPS)
        integer :: k

        stat%code = STATUS_OK
        d%path = path
        d%name = deck_name(path)
        d%text = ''
        do k = 1, size(ls)
            if (k > 1) d%text = d%text//achar(10)
            d%text = d%text//ls(k)%s
        end do
        call check_group_names(ls, stat, seen)
        if (stat%code /= STATUS_OK) return
        if (size(ls) == 0) then
            call set_error(stat, ERR_DECK, 'the deck is empty or not a regular file; '// &
                           'allowed: a namelist file with &suspension and &body')
            return
        end if
        ! Values such as 1e400 overflow inside the run-time library: read without traps, the
        ! finiteness checks catch the result.
        call traps_off(halting)
        call read_group('scene', .false., SPEC_SCENE)
        call read_group('suspension', .true., SPEC_SUSPENSION)
        call read_group('body', .true., SPEC_BODY)
        call read_group('start', .false., SPEC_START)
        call read_group('integration', .false., SPEC_INTEGRATION)
        call read_group('cables', .false., SPEC_CABLES)
        call read_group('floquet', .false., SPEC_FLOQUET)
        call read_group('chart', .false., SPEC_CHART)
        call read_group('output', .false., SPEC_OUTPUT)
        call read_group('design', .false., SPEC_DESIGN)
        call read_group('damping', .false., SPEC_DAMPING)
        call read_group('measurement', .false., SPEC_MEASUREMENT)
        call read_group('tensor', .false., SPEC_TENSOR)
        call traps_restore(halting)
        if (stat%code /= STATUS_OK) return

        call check_scene(d, stat)
        call check_suspension(d, stat)
        call check_body(d, stat)
        call check_start(d, stat)
        call check_integration(d, stat)
        call check_cables(d, stat)
        call check_floquet(d, stat)
        call check_chart(d, stat)
        call check_output(d, stat)
        if (analysis_requested(d, 'design')) call check_design(d, stat)
        call check_damping(d, stat)
        call check_measurement(d, stat)
        call check_tensor(d, stat)
        call check_measuring(d, stat)
        if (stat%code /= STATUS_OK) return
        d%record_path = ''
        if (len_trim(d%record) > 0) d%record_path = record_in_folder(path, d%record)
        d%trials_path = ''
        if (len_trim(d%trials) > 0) d%trials_path = record_in_folder(path, d%trials)
        d%tensor_hangs_path = ''
        if (len_trim(d%tensor_hangs) > 0) d%tensor_hangs_path = record_in_folder(path, &
                                                                                 d%tensor_hangs)
        call reduce_angles(d)

    contains

        !> Read one group (when present) with its read_<group>, and explain any failure.
        subroutine read_group(grp, required, spec)
            character(len=*), intent(in) :: grp         !! group name
            logical, intent(in) :: required             !! absence is an error
            character(len=*), intent(in) :: spec        !! variables, see SPEC_*
            logical :: found, complete
            character(len=:), allocatable :: items, rec, why
            integer, allocatable :: breaks(:)
            integer :: ios
            character(len=512) :: msg

            if (stat%code /= STATUS_OK) return
            if (index(seen, ' '//grp//' ') == 0) then   ! no line starts the group
                if (required) call set_error(stat, ERR_DECK, '&'//grp// &
                    ' group missing; allowed: a deck with &suspension and &body (both required)')
                return
            end if
            call scan_group(ls, grp, found, complete, items, breaks, rec)
            if (.not. found) then
                if (required) call set_error(stat, ERR_DECK, '&'//grp// &
                    ' group missing; allowed: a deck with &suspension and &body (both required)')
                return
            end if
            ! what the run-time library cannot be trusted with never reaches it
            why = subscript_problem(items, breaks)
            if (len(why) == 0) why = long_text(items)
            if (len(why) > 0) then
                call set_error(stat, ERR_DECK, with_allowed('cannot read namelist group &'// &
                               grp//': '//why, '', spec))
                return
            end if
            if (.not. complete) then
                call set_error(stat, ERR_DECK, 'cannot read namelist group &'//grp// &
                    ': no closing ''/'' before the end of the file (truncated deck?); '// &
                    'allowed: each group closed by ''/'' (or &end)')
                return
            end if
            msg = ''
            select case (grp)
            case ('scene')
                call read_scene(rec, d, ios, msg)
            case ('suspension')
                call read_suspension(rec, d, ios, msg)
            case ('body')
                call read_body(rec, d, ios, msg)
            case ('start')
                call read_start(rec, d, ios, msg)
            case ('integration')
                call read_integration(rec, d, ios, msg)
            case ('cables')
                call read_cables(rec, d, ios, msg)
            case ('floquet')
                call read_floquet(rec, d, ios, msg)
            case ('chart')
                call read_chart(rec, d, ios, msg)
            case ('output')
                call read_output(rec, d, ios, msg)
            case ('design')
                call read_design(rec, d, ios, msg)
            case ('damping')
                call read_damping(rec, d, ios, msg)
            case ('tensor')
                call read_tensor(rec, d, ios, msg)
            case default
                call read_measurement(rec, d, ios, msg)
            end select
            if (ios == 0) return
            why = explain(items, grp, spec)
            if (len(why) > 0) then
                call set_error(stat, ERR_DECK, with_allowed('cannot read namelist group &'// &
                               grp//': '//why, ' (reader: '//trim(msg)//')', spec))
            else
                call set_error(stat, ERR_DECK, with_allowed('cannot read namelist group &'// &
                               grp//': '//trim(msg), '', spec))
            end if
        end subroutine read_group


    end subroutine parse_deck

    ! ---------------------------------------------------------------- read_<group>
    ! Each reads its group from `rec` (the group as one record, from scan_group) into d: the
    ! namelist's variables take d's values (the defaults), the read changes those given, and
    ! d takes them back.  A namelist of its own per group keeps the names of different
    ! groups apart (amplitude in &start and &floquet, damping in &cables and a group).

    !> &scene title, analyses, model.
    subroutine read_scene(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: title, analyses, model
        namelist /scene/ title, analyses, model
        title = d%title
        analyses = d%analyses
        model = d%model
        read (rec, nml=scene, iostat=ios, iomsg=msg)
        d%title = title
        d%analyses = analyses
        d%model = model
    end subroutine read_scene

    !> &suspension b, b_prime, l, l_prime, g, cables, radius, radius_prime.
    subroutine read_suspension(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: b, b_prime, l, l_prime, g, radius, radius_prime
        integer :: cables
        namelist /suspension/ b, b_prime, l, l_prime, g, cables, radius, radius_prime
        b = NOT_GIVEN
        b_prime = NOT_GIVEN
        l = NOT_GIVEN
        l_prime = NOT_GIVEN
        g = NOT_GIVEN
        radius = NOT_GIVEN
        radius_prime = NOT_GIVEN
        cables = -huge(1)
        read (rec, nml=suspension, iostat=ios, iomsg=msg)
        call take('b', b, d%b)
        call take('b_prime', b_prime, d%b_prime)
        call take('l', l, d%l)
        call take('l_prime', l_prime, d%l_prime)
        call take('g', g, d%g)
        call take('radius', radius, d%radius)
        call take('radius_prime', radius_prime, d%radius_prime)
        if (cables /= -huge(1)) then
            d%cables = cables
            call note_given(d, 'cables')
        end if
    contains
        subroutine take(name, v, x)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: v
            real(dp), intent(inout) :: x
            if (v == NOT_GIVEN) return
            x = v
            call note_given(d, name)
        end subroutine take
    end subroutine read_suspension

    !> Record that the deck gave the tracked input `name`.
    pure subroutine note_given(d, name)
        type(deck_t), intent(inout) :: d
        character(len=*), intent(in) :: name
        if (.not. allocated(d%given)) d%given = ' '
        if (index(d%given, ' '//name//' ') == 0) d%given = d%given//name//' '
    end subroutine note_given

    !> True when the deck gave the tracked input `name` itself (GIVEN_TRACKED).
    pure logical function deck_gave(d, name)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: name
        deck_gave = .false.
        if (allocated(d%given)) deck_gave = index(d%given, ' '//name//' ') > 0
    end function deck_gave

    !> &body mass, inertia, r, lambda, btilde, sway_depth.
    subroutine read_body(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: mass, inertia(3), r, lambda, cg_depth, cg_offset, btilde(3, 3), sway_depth
        namelist /body/ mass, inertia, r, lambda, cg_depth, cg_offset, btilde, sway_depth
        mass = NOT_GIVEN
        inertia = NOT_GIVEN
        r = NOT_GIVEN
        lambda = NOT_GIVEN
        cg_depth = NOT_GIVEN
        cg_offset = NOT_GIVEN
        btilde = d%btilde
        sway_depth = d%sway_depth
        read (rec, nml=body, iostat=ios, iomsg=msg)
        call take('mass', mass, d%mass)
        call take('r', r, d%r)
        call take('lambda', lambda, d%lambda)
        call take('cg_depth', cg_depth, d%cg_depth)
        call take('cg_offset', cg_offset, d%cg_offset)
        if (any(inertia /= NOT_GIVEN)) call note_given(d, 'inertia')
        where (inertia /= NOT_GIVEN) d%inertia = inertia
        d%btilde = btilde
        d%sway_depth = sway_depth
    contains
        subroutine take(name, v, x)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: v
            real(dp), intent(inout) :: x
            if (v == NOT_GIVEN) return
            x = v
            call note_given(d, name)
        end subroutine take
    end subroutine read_body

    !> &start mode, amplitude, tilt, theta, theta_dot.
    subroutine read_start(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: mode
        real(dp) :: amplitude, tilt, theta(4), theta_dot(4)
        namelist /start/ mode, amplitude, tilt, theta, theta_dot
        mode = d%mode
        amplitude = d%amplitude
        tilt = d%tilt
        theta = d%theta
        theta_dot = d%theta_dot
        read (rec, nml=start, iostat=ios, iomsg=msg)
        d%mode = mode
        d%amplitude = amplitude
        d%tilt = tilt
        d%theta = theta
        d%theta_dot = theta_dot
    end subroutine read_start

    !> &integration tau_end, dtau_out, rtol, atol, error_estimate, method, sensitivities,
    !! sensitivity_error_control.
    subroutine read_integration(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: tau_end, dtau_out, rtol, atol
        logical :: error_estimate, sensitivity_error_control
        character(len=256) :: method, sensitivities
        namelist /integration/ tau_end, dtau_out, rtol, atol, error_estimate, method, &
            sensitivities, sensitivity_error_control
        tau_end = d%tau_end
        dtau_out = d%dtau_out
        rtol = d%rtol
        atol = d%atol
        error_estimate = d%error_estimate
        method = d%method
        sensitivities = d%sensitivities
        sensitivity_error_control = d%sensitivity_error_control
        read (rec, nml=integration, iostat=ios, iomsg=msg)
        d%tau_end = tau_end
        d%dtau_out = dtau_out
        d%rtol = rtol
        d%atol = atol
        d%error_estimate = error_estimate
        d%method = method
        d%sensitivities = sensitivities
        d%sensitivity_error_control = sensitivity_error_control
    end subroutine read_integration

    !> &cables stiffness, damping.
    subroutine read_cables(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: stiffness, damping
        namelist /cables/ stiffness, damping
        stiffness = d%cable_stiffness
        damping = d%cable_damping
        read (rec, nml=cables, iostat=ios, iomsg=msg)
        d%cable_stiffness = stiffness
        d%cable_damping = damping
    end subroutine read_cables

    !> &floquet amplitude, segments, rtol.
    subroutine read_floquet(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: amplitude, rtol
        integer :: segments
        namelist /floquet/ amplitude, segments, rtol
        amplitude = d%floquet_amplitude
        segments = d%floquet_segments
        rtol = d%floquet_rtol
        read (rec, nml=floquet, iostat=ios, iomsg=msg)
        d%floquet_amplitude = amplitude
        d%floquet_segments = segments
        d%floquet_rtol = rtol
    end subroutine read_floquet

    !> &chart x, x_min, x_max, nx, y, y_min, y_max, ny.
    subroutine read_chart(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: x, y
        real(dp) :: x_min, x_max, y_min, y_max
        integer :: nx, ny
        namelist /chart/ x, x_min, x_max, nx, y, y_min, y_max, ny
        x = d%chart_x
        x_min = d%chart_x_min
        x_max = d%chart_x_max
        nx = d%chart_nx
        y = d%chart_y
        y_min = d%chart_y_min
        y_max = d%chart_y_max
        ny = d%chart_ny
        read (rec, nml=chart, iostat=ios, iomsg=msg)
        d%chart_x = x
        d%chart_x_min = x_min
        d%chart_x_max = x_max
        d%chart_nx = nx
        d%chart_y = y
        d%chart_y_min = y_min
        d%chart_y_max = y_max
        d%chart_ny = ny
    end subroutine read_chart

    !> &output columns.
    subroutine read_output(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=512) :: columns
        namelist /output/ columns
        columns = d%columns
        read (rec, nml=output, iostat=ios, iomsg=msg)
        d%columns = columns
    end subroutine read_output

    !> &design l_min, l_max, nl, b_min, b_max, nb, b_prime_min, b_prime_max, nb_prime,
    !! amplitude_max, n_amplitudes, amplitude_measure, u_mass, u_l, u_b, u_period (into d's
    !! design_* values).
    subroutine read_design(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! design_* values: defaults in, read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: l_min, l_max, b_min, b_max, amplitude_max, u_mass, u_l, u_b, u_period
        real(dp) :: b_prime_min, b_prime_max, amplitude_measure
        integer :: nl, nb, n_amplitudes, nb_prime
        namelist /design/ l_min, l_max, nl, b_min, b_max, nb, amplitude_max, n_amplitudes, &
            u_mass, u_l, u_b, u_period, b_prime_min, b_prime_max, nb_prime, amplitude_measure
        l_min = d%design_l_min
        l_max = d%design_l_max
        nl = d%design_nl
        b_min = d%design_b_min
        b_max = d%design_b_max
        nb = d%design_nb
        b_prime_min = d%design_b_prime_min
        b_prime_max = d%design_b_prime_max
        nb_prime = d%design_nb_prime
        amplitude_measure = d%design_amplitude_measure
        amplitude_max = d%design_amplitude_max
        n_amplitudes = d%design_n_amplitudes
        u_mass = d%design_u_mass
        u_l = d%design_u_l
        u_b = d%design_u_b
        u_period = d%design_u_period
        read (rec, nml=design, iostat=ios, iomsg=msg)
        d%design_l_min = l_min
        d%design_l_max = l_max
        d%design_nl = nl
        d%design_b_min = b_min
        d%design_b_max = b_max
        d%design_nb = nb
        d%design_b_prime_min = b_prime_min
        d%design_b_prime_max = b_prime_max
        d%design_nb_prime = nb_prime
        d%design_amplitude_measure = amplitude_measure
        d%design_amplitude_max = amplitude_max
        d%design_n_amplitudes = n_amplitudes
        d%design_u_mass = u_mass
        d%design_u_l = u_l
        d%design_u_b = u_b
        d%design_u_period = u_period
    end subroutine read_design

    !> &damping c_v, c_q.
    subroutine read_damping(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! c_v, c_q: in defaults, out as read
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: c_v, c_q
        namelist /damping/ c_v, c_q
        c_v = d%c_v
        c_q = d%c_q
        read (rec, nml=damping, iostat=ios, iomsg=msg)
        d%c_v = c_v
        d%c_q = c_q
    end subroutine read_damping

    !> &tensor hangs, the standard uncertainties of the hangs' inputs, monte_carlo, seed, cg,
    !! plan.
    subroutine read_tensor(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! defaults in, values read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: hangs
        real(dp) :: u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude
        real(dp) :: u_direction, cg(3)
        integer :: monte_carlo, seed, plan
        namelist /tensor/ hangs, u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, &
            u_amplitude, u_direction, monte_carlo, seed, cg, plan
        hangs = d%tensor_hangs
        u_mass = d%tensor_u(1)
        u_l = d%tensor_u(2)
        u_l_prime = d%tensor_u(3)
        u_b = d%tensor_u(4)
        u_b_prime = d%tensor_u(5)
        u_g = d%tensor_u(6)
        u_period = d%tensor_u(7)
        u_amplitude = d%tensor_u(8)
        u_direction = d%tensor_u_direction
        monte_carlo = d%tensor_monte_carlo
        seed = d%tensor_seed
        plan = d%tensor_plan
        cg = NOT_GIVEN
        read (rec, nml=tensor, iostat=ios, iomsg=msg)
        d%tensor_hangs = hangs
        d%tensor_u = [u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude]
        d%tensor_u_direction = u_direction
        d%tensor_monte_carlo = monte_carlo
        d%tensor_seed = seed
        d%tensor_plan = plan
        d%tensor_cg_given = any(cg /= NOT_GIVEN)
        if (d%tensor_cg_given) d%tensor_cg = merge(cg, 0.0_dp, cg /= NOT_GIVEN)
    end subroutine read_tensor

    !> &measurement; n_periods counts the leading periods given (check_measurement refuses
    !! gaps).
    subroutine read_measurement(rec, d, ios, msg)
        character(len=*), intent(in) :: rec         !! the group as one record
        type(deck_t), intent(inout) :: d            !! in defaults, out as read
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: periods(MAX_PERIODS), amplitudes(MAX_PERIODS), cycles(MAX_PERIODS)
        character(len=256) :: record, quantity, estimate, trials, record_units, loss
        real(dp) :: u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude
        real(dp) :: u_inertia(2), u_cg_depth, u_cg_offset, u_r, u_lambda
        real(dp) :: tare_i1, u_tare_i1, tare_mass, added_inertia, u_added_inertia
        integer :: monte_carlo, seed, record_columns(3)
        namelist /measurement/ periods, amplitudes, cycles, record, quantity, estimate, u_mass, &
            u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude, monte_carlo, seed, &
            trials, record_columns, record_units, loss, u_inertia, u_cg_depth, u_cg_offset, &
            u_r, u_lambda, tare_i1, u_tare_i1, tare_mass, added_inertia, u_added_inertia
        periods = d%periods
        amplitudes = d%amplitudes
        cycles = PERIOD_UNSET
        record = d%record
        quantity = ''
        estimate = d%estimate
        u_mass = d%u_mass
        u_l = d%u_l
        u_l_prime = d%u_l_prime
        u_b = d%u_b
        u_b_prime = d%u_b_prime
        u_g = d%u_g
        u_period = d%u_period
        u_amplitude = d%u_amplitude
        monte_carlo = d%monte_carlo
        seed = d%seed
        trials = d%trials
        record_columns = -1
        record_units = d%record_units
        loss = d%loss
        u_inertia = PERIOD_UNSET
        u_cg_depth = d%u_cg_depth
        u_cg_offset = d%u_cg_offset
        u_r = d%u_r
        u_lambda = d%u_lambda
        tare_i1 = d%tare_i1
        u_tare_i1 = d%u_tare_i1
        tare_mass = d%tare_mass
        added_inertia = d%added_inertia
        u_added_inertia = d%u_added_inertia
        read (rec, nml=measurement, iostat=ios, iomsg=msg)
        d%periods = periods
        d%amplitudes = amplitudes
        d%cycles = cycles
        d%record = record
        if (len_trim(quantity) > 0) then
            d%quantity = quantity
            call note_given(d, 'quantity')
        end if
        d%estimate = estimate
        d%u_mass = u_mass
        d%u_l = u_l
        d%u_l_prime = u_l_prime
        d%u_b = u_b
        d%u_b_prime = u_b_prime
        d%u_g = u_g
        d%u_period = u_period
        d%u_amplitude = u_amplitude
        d%monte_carlo = monte_carlo
        d%seed = seed
        d%trials = trials
        if (any(record_columns(1:2) /= -1)) then
            d%record_columns = max(0, record_columns)
            call note_given(d, 'record_columns')
        end if
        d%record_units = record_units
        d%loss = loss
        ! one value of u_inertia serves I2 and I3
        d%u_inertia = 0.0_dp
        if (u_inertia(1) /= PERIOD_UNSET) d%u_inertia = u_inertia(1)
        if (u_inertia(2) /= PERIOD_UNSET) d%u_inertia(2) = u_inertia(2)
        d%u_cg_depth = u_cg_depth
        d%u_cg_offset = u_cg_offset
        d%u_r = u_r
        d%u_lambda = u_lambda
        d%tare_i1 = tare_i1
        d%u_tare_i1 = u_tare_i1
        d%tare_mass = tare_mass
        d%added_inertia = added_inertia
        d%u_added_inertia = u_added_inertia
        d%n_periods = 0
        do while (d%n_periods < MAX_PERIODS)
            if (d%periods(d%n_periods + 1) == PERIOD_UNSET) exit
            d%n_periods = d%n_periods + 1
        end do
    end subroutine read_measurement

    !> A record file named in a deck: as given when absolute, else relative to the deck's
    !! folder.
    pure function record_in_folder(deck_path, record) result(p)
        character(len=*), intent(in) :: deck_path   !! the deck as given
        character(len=*), intent(in) :: record      !! &measurement record
        character(len=:), allocatable :: p
        integer :: i
        p = trim(adjustl(record))
        if (p(1:1) == '/') return
        i = index(deck_path, '/', back=.true.)
        if (i > 0) p = deck_path(1:i)//p
    end function record_in_folder

    !> True when `word` is one of the blank-separated words of d%analyses.
    logical function analysis_requested(d, word)
        type(deck_t), intent(in) :: d               !! the deck
        character(len=*), intent(in) :: word        !! analysis name, e.g. 'simulate'
        integer :: i1, i2
        character(len=len(d%analyses)) :: list
        analysis_requested = .false.
        list = lower(d%analyses)
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            if (list(i1:i2) == lower(trim(adjustl(word)))) then
                analysis_requested = .true.
                return
            end if
        end do
    end function analysis_requested

    !> True when the blank-separated word `word` (e.g. 'c_q') is in &measurement estimate.
    pure logical function estimated(d, word)
        type(deck_t), intent(in) :: d               !! the deck
        character(len=*), intent(in) :: word        !! one of ESTIMATES_ALLOWED
        estimated = index(' '//lower(d%estimate)//' ', ' '//lower(trim(word))//' ') > 0
    end function estimated

    !> Write the effective deck as '# ' comment lines, one namelist-like line per group
    !! (&floquet and &chart only when that analysis is requested); the reals are the
    !! shortest decimals that read back exactly.
    subroutine deck_echo(d, unit, ios)
        type(deck_t), intent(in) :: d               !! the deck
        integer, intent(in) :: unit                 !! open formatted unit
        integer, intent(inout) :: ios               !! writer's iostat: nothing written when
                                                    !! /= 0 on entry; the first failure
        integer :: i
        character(len=:), allocatable :: line
        call put('# deck '//d%path)
        call put('# &scene title = '//quoted(d%title)//', analyses = '//quoted(d%analyses)// &
                 ', model = '//quoted(d%model)//' /')
        line = '# &suspension b = '//rshort(d%b)//', b_prime = '//rshort(d%b_prime)// &
            ', l = '//rshort(d%l)//', l_prime = '//rshort(d%l_prime)//', g = '//rshort(d%g)
        if (d%cables /= 2) line = line//', cables = '//itoa(d%cables)//', radius = '// &
            rshort(d%radius)//', radius_prime = '//rshort(d%radius_prime)
        call put(line//' /')
        line = '# &body mass = '//rshort(d%mass)//', inertia = '//rlist_short(d%inertia)// &
            ', r = '//rshort(d%r)//', lambda = '//rshort(d%lambda)
        if (deck_gave(d, 'cg_depth') .or. deck_gave(d, 'cg_offset')) line = line// &
            ', cg_depth = '//rshort(d%cg_depth)//', cg_offset = '//rshort(d%cg_offset)
        do i = 1, 3
            line = line//', btilde('//achar(iachar('0') + i)//',:) = '//rlist_short(d%btilde(i, :))
        end do
        call put(line//', sway_depth = '//rshort(d%sway_depth)//' /')
        call put('# &start mode = '//quoted(d%mode)//', amplitude = '//rshort(d%amplitude)// &
                 ', tilt = '//rshort(d%tilt)//', theta = '//rlist_short(d%theta)// &
                 ', theta_dot = '//rlist_short(d%theta_dot)//' /')
        line = '.false.'
        if (d%error_estimate) line = '.true.'
        call put('# &integration tau_end = '//rshort(d%tau_end)//', dtau_out = '// &
                 rshort(d%dtau_out)//', rtol = '//rshort(d%rtol)//', atol = '//rshort(d%atol)// &
                 ', error_estimate = '//line//', method = '//quoted(d%method)// &
                 ', sensitivities = '//quoted(d%sensitivities)// &
                 ', sensitivity_error_control = '// &
                 trim(merge('.true. ', '.false.', d%sensitivity_error_control))//' /')
        if (trim(d%model) == 'elastic') call put('# &cables stiffness = '// &
            rshort(d%cable_stiffness)//', damping = '//rshort(d%cable_damping)//' /')
        if (analysis_requested(d, 'floquet')) call put('# &floquet amplitude = '// &
            rshort(d%floquet_amplitude)//', segments = '//itoa(d%floquet_segments)// &
            ', rtol = '//rshort(d%floquet_rtol)//' /')
        if (analysis_requested(d, 'chart')) call put('# &chart x = '// &
            quoted(d%chart_x)//', x_min = '//rshort(d%chart_x_min)//', x_max = '// &
            rshort(d%chart_x_max)//', nx = '//itoa(d%chart_nx)//', y = '//quoted(d%chart_y)// &
            ', y_min = '//rshort(d%chart_y_min)//', y_max = '//rshort(d%chart_y_max)// &
            ', ny = '//itoa(d%chart_ny)//' /')
        if (analysis_requested(d, 'design')) call put('# &design l_min = '// &
            rshort(d%design_l_min)//', l_max = '//rshort(d%design_l_max)//', nl = '// &
            itoa(d%design_nl)//', b_min = '//rshort(d%design_b_min)//', b_max = '// &
            rshort(d%design_b_max)//', nb = '//itoa(d%design_nb)//', b_prime_min = '// &
            rshort(d%design_b_prime_min)//', b_prime_max = '//rshort(d%design_b_prime_max)// &
            ', nb_prime = '//itoa(d%design_nb_prime)//', amplitude_max = '// &
            rshort(d%design_amplitude_max)//', n_amplitudes = '//itoa(d%design_n_amplitudes)// &
            ', amplitude_measure = '//rshort(d%design_amplitude_measure)// &
            ', u_mass = '//rshort(d%design_u_mass)//', u_l = '//rshort(d%design_u_l)// &
            ', u_b = '//rshort(d%design_u_b)//', u_period = '//rshort(d%design_u_period)//' /')
        if (trim(d%columns) /= OUTPUT_COLUMNS) call put('# &output columns = '// &
            quoted(d%columns)//' /')
        if (d%c_v /= 0.0_dp .or. d%c_q /= 0.0_dp .or. analysis_requested(d, 'identify')) &
            call put('# &damping c_v = '//rshort(d%c_v)//', c_q = '//rshort(d%c_q)//' /')
        if (analysis_requested(d, 'identify')) then
            line = '# &measurement'
            if (d%n_periods > 0) line = line//' periods = '// &
                rlist_short(d%periods(1:d%n_periods))//', amplitudes = '// &
                rlist_short(d%amplitudes(1:d%n_periods))//','
            if (len_trim(d%record) > 0) line = line//' record = '//quoted(d%record)// &
                ', quantity = '//quoted(d%quantity)//','
            if (d%n_periods > 0) then
                if (any(d%cycles(1:d%n_periods) /= 1.0_dp)) line = line//' cycles = '// &
                    rlist_short(d%cycles(1:d%n_periods))//','
            end if
            if (len_trim(d%trials) > 0) line = line//' trials = '//quoted(d%trials)//','
            if (deck_gave(d, 'record_columns')) line = line//' record_columns = '// &
                itoa(d%record_columns(1))//', '//itoa(d%record_columns(2))//', '// &
                itoa(d%record_columns(3))//','
            if (len_trim(d%record_units) > 0) line = line//' record_units = '// &
                quoted(d%record_units)//','
            if (trim(d%loss) /= 'squares') line = line//' loss = '//quoted(d%loss)//','
            line = line//' estimate = '//quoted(d%estimate)//', u_mass = '// &
                rshort(d%u_mass)//', u_l = '//rshort(d%u_l)//', u_l_prime = '// &
                rshort(d%u_l_prime)//', u_b = '//rshort(d%u_b)//', u_b_prime = '// &
                rshort(d%u_b_prime)//', u_g = '//rshort(d%u_g)//', u_period = '// &
                rshort(d%u_period)//', u_amplitude = '//rshort(d%u_amplitude)
            if (any(d%u_inertia > 0.0_dp)) line = line//', u_inertia = '// &
                rlist_short(d%u_inertia)
            if (d%u_cg_depth > 0.0_dp .or. d%u_cg_offset > 0.0_dp) line = line// &
                ', u_cg_depth = '//rshort(d%u_cg_depth)//', u_cg_offset = '//rshort(d%u_cg_offset)
            if (d%u_r > 0.0_dp .or. d%u_lambda > 0.0_dp) line = line//', u_r = '// &
                rshort(d%u_r)//', u_lambda = '//rshort(d%u_lambda)
            if (d%tare_i1 > 0.0_dp .or. d%tare_mass > 0.0_dp .or. d%u_tare_i1 > 0.0_dp) &
                line = line//', tare_i1 = '// &
                rshort(d%tare_i1)//', u_tare_i1 = '//rshort(d%u_tare_i1)//', tare_mass = '// &
                rshort(d%tare_mass)
            if (d%added_inertia > 0.0_dp .or. d%u_added_inertia > 0.0_dp) &
                line = line//', added_inertia = '// &
                rshort(d%added_inertia)//', u_added_inertia = '//rshort(d%u_added_inertia)
            call put(line//', monte_carlo = '//itoa(d%monte_carlo)//', seed = '// &
                     itoa(d%seed)//' /')
        end if
        if (analysis_requested(d, 'tensor')) then
            line = '# &tensor hangs = '//quoted(d%tensor_hangs)//', u_mass = '// &
                rshort(d%tensor_u(1))//', u_l = '//rshort(d%tensor_u(2))//', u_l_prime = '// &
                rshort(d%tensor_u(3))//', u_b = '//rshort(d%tensor_u(4))//', u_b_prime = '// &
                rshort(d%tensor_u(5))//', u_g = '//rshort(d%tensor_u(6))//', u_period = '// &
                rshort(d%tensor_u(7))//', u_amplitude = '//rshort(d%tensor_u(8))// &
                ', u_direction = '//rshort(d%tensor_u_direction)//', monte_carlo = '// &
                itoa(d%tensor_monte_carlo)//', seed = '//itoa(d%tensor_seed)
            if (d%tensor_cg_given) line = line//', cg = '//rlist_short(d%tensor_cg)
            if (d%tensor_plan > 0) line = line//', plan = '//itoa(d%tensor_plan)
            call put(line//' /')
        end if

    contains

        subroutine put(text)
            character(len=*), intent(in) :: text
            if (ios == 0) write (unit, '(a)', iostat=ios) text
        end subroutine put

    end subroutine deck_echo

    !> File name without directory and without a trailing '.nml'.
    pure function deck_name(path) result(nm)
        character(len=*), intent(in) :: path        !! deck path
        character(len=:), allocatable :: nm
        integer :: i
        i = index(path, '/', back=.true.)
        nm = trim(path(i + 1:))
        if (len(nm) > 4) then
            if (nm(len(nm) - 3:) == '.nml') nm = nm(1:len(nm) - 4)
        end if
        if (len(nm) == 0) nm = 'deck'
    end function deck_name

end module deck
