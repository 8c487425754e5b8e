!> The input deck: a namelist file with the groups &scene, &suspension, &body, &start,
!! &integration, &cables, &floquet, &chart, &design, &output, &damping and &measurement
!! (see input/*.nml).  read_deck reads and validates it;
!! every problem is an ERR_DECK status whose message names the deck, the group, the variable
!! and its value, what is wrong and what is allowed.  Cable reachability is checked by the
!! geometry module.
module deck
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_usual, ieee_support_halting, &
        ieee_get_halting_mode, ieee_set_halting_mode, ieee_set_flag
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, sci, lead_zero
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
    character(len=*), parameter, public :: ESTIMATES_ALLOWED = 'I1 c_v c_q amplitude t0'
    !> Words allowed in &measurement quantity: column 2 of a record.
    character(len=*), parameter, public :: QUANTITIES_ALLOWED = 'angle rate'

    type, public :: deck_t
        character(len=:), allocatable :: path        !! deck file as given
        character(len=:), allocatable :: name        !! file name without directory and .nml
        ! &scene
        character(len=256) :: title = ''
        character(len=256) :: analyses = 'simulate'
        character(len=16)  :: model = 'kane'          !! MODELS_ALLOWED: 'kane' or 'elastic'
        ! &suspension (lengths in any one unit)
        real(dp) :: b = 1.0_dp, b_prime = 1.0_dp, l = 2.0_dp, l_prime = 2.0_dp, g = 1.0_dp
        ! &body
        real(dp) :: mass = 1.0_dp
        real(dp) :: inertia(3) = [0.125_dp, 0.1458333333333333_dp, 0.1458333333333333_dp]
        real(dp) :: r = 0.7071067811865476_dp, lambda = 0.7853981633974483_dp
        !> default identity; btilde(i,:) is row i as printed in the paper
        real(dp) :: btilde(3,3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                           0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
        real(dp) :: sway_depth = 1.0_dp
        ! &start
        character(len=16) :: mode = 'raised'
        real(dp) :: amplitude = 45.0_dp, tilt = 0.0_dp     !! degrees, radians
        real(dp) :: theta(4) = 0.0_dp, theta_dot(4) = 0.0_dp
        ! &integration
        real(dp) :: tau_end = 60.0_dp, dtau_out = 0.05_dp, rtol = 1.0e-10_dp, atol = 1.0e-12_dp
        logical  :: error_estimate = .false.
        character(len=16) :: method = 'auto'      !! METHODS_ALLOWED: the integrator
        ! &cables (model = 'elastic' only)
        real(dp) :: cable_stiffness = 1.0e6_dp    !! EA/(m g) of each cable, 1 <= k <= 1e12
        real(dp) :: cable_damping = 0.05_dp       !! damping ratio zeta of each cable, 0..10
        ! &floquet
        real(dp) :: floquet_amplitude = 45.0_dp   !! degrees of theta4, 0 < a < 180
        integer  :: floquet_segments = 1          !! shooting segments, 1..64
        real(dp) :: floquet_rtol = 1.0e-10_dp     !! 1e-14 <= rtol < 1e-2
        ! &chart (axis variables: see CHART_VARIABLES)
        character(len=16) :: chart_x = 'l', chart_y = 'amplitude'
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
        real(dp) :: design_amplitude_max = 50.0_dp  !! degrees, 0 < a <= 90
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
    end type deck_t

    public :: read_deck, analysis_requested, deck_echo, estimated, count_words
    public :: traps_off, traps_restore, read_line, rshort

    !> Words allowed in &scene analyses.
    character(len=*), parameter :: ANALYSES_ALLOWED = &
        'simulate floquet chart work_precision design identify'
    !> Namelist groups a deck may contain.
    character(len=*), parameter :: GROUPS_ALLOWED = 'scene suspension body start '// &
        'integration cables floquet chart output design damping measurement'
    !> Words allowed in &scene model.
    character(len=*), parameter :: MODELS_ALLOWED = 'kane elastic'
    !> Words allowed in &integration method: 'auto' (radau for model = 'elastic', lsoda for
    !! the paper's model), 'lsoda', 'radau'.
    character(len=*), parameter :: METHODS_ALLOWED = 'auto lsoda radau'
    !> Words allowed in &chart x and y.
    character(len=*), parameter :: CHART_VARIABLES = 'l b amplitude r lambda inertia_ratio'
    !> Variables of each group with their kind (r real, i integer, c character, l logical)
    !! and size; used only to explain a namelist read error.
    character(len=*), parameter :: SPEC_SCENE = 'title:c1 analyses:c1 model:c1'
    character(len=*), parameter :: SPEC_SUSPENSION = 'b:r1 b_prime:r1 l:r1 l_prime:r1 g:r1'
    character(len=*), parameter :: SPEC_BODY = &
        'mass:r1 inertia:r3 r:r1 lambda:r1 btilde:r9 sway_depth:r1'
    character(len=*), parameter :: SPEC_START = 'mode:c1 amplitude:r1 tilt:r1 theta:r4 theta_dot:r4'
    character(len=*), parameter :: SPEC_INTEGRATION = &
        'tau_end:r1 dtau_out:r1 rtol:r1 atol:r1 error_estimate:l1 method:c1'
    character(len=*), parameter :: SPEC_CABLES = 'stiffness:r1 damping:r1'
    character(len=*), parameter :: SPEC_FLOQUET = 'amplitude:r1 segments:i1 rtol:r1'
    character(len=*), parameter :: SPEC_CHART = &
        'x:c1 x_min:r1 x_max:r1 nx:i1 y:c1 y_min:r1 y_max:r1 ny:i1'
    character(len=*), parameter :: SPEC_OUTPUT = 'columns:c1'
    character(len=*), parameter :: SPEC_DESIGN = 'l_min:r1 l_max:r1 nl:i1 b_min:r1 b_max:r1 '// &
        'nb:i1 amplitude_max:r1 n_amplitudes:i1 u_mass:r1 u_l:r1 u_b:r1 u_period:r1'
    character(len=*), parameter :: SPEC_DAMPING = 'c_v:r1 c_q:r1'
    character(len=*), parameter :: SPEC_MEASUREMENT = 'periods:r100 amplitudes:r100 '// &
        'record:c1 quantity:c1 estimate:c1 u_mass:r1 u_l:r1 u_l_prime:r1 u_b:r1 '// &
        'u_b_prime:r1 u_g:r1 u_period:r1 u_amplitude:r1 monte_carlo:i1 seed:i1'
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
    integer, parameter :: MAX_LINE = 4096               !! longest deck line (characters)
    integer, parameter :: MAX_DECK_BYTES = 1000000      !! largest deck (bytes)
    integer, parameter :: CLIP_LEN = 60                 !! longest value quoted in a message
    integer, parameter :: MAX_TEXT = 256                !! longest quoted value (title, words)

contains

    !> Read and validate the deck at `path` into d.  Absent optional groups keep defaults;
    !! &suspension and &body are required.
    subroutine read_deck(path, d, stat)
        character(len=*), intent(in) :: path        !! deck file
        type(deck_t), intent(out) :: d              !! the effective deck (defaults + file)
        type(status_t), intent(out) :: stat         !! ERR_DECK with a message on any problem
        ! namelist variables (names fixed by the deck format)
        character(len=256) :: title
        character(len=1024) :: analyses
        character(len=256) :: model, mode
        real(dp) :: b, b_prime, l, l_prime, g
        real(dp) :: mass, inertia(3), r, lambda, btilde(3,3), sway_depth
        real(dp) :: amplitude, tilt, theta(4), theta_dot(4)
        real(dp) :: tau_end, dtau_out, rtol, atol
        logical :: error_estimate
        character(len=256) :: method
        real(dp) :: stiffness, damping
        character(len=256) :: x, y
        real(dp) :: x_min, x_max, y_min, y_max
        integer :: nx, ny
        character(len=1024) :: columns
        ! &floquet's amplitude and rtol share names with &start and &integration, so its
        ! namelist lives in read_floquet; these hold its values here
        real(dp) :: fq_amplitude, fq_rtol
        integer :: fq_segments
        namelist /scene/ title, analyses, model
        namelist /suspension/ b, b_prime, l, l_prime, g
        namelist /body/ mass, inertia, r, lambda, btilde, sway_depth
        namelist /start/ mode, amplitude, tilt, theta, theta_dot
        namelist /integration/ tau_end, dtau_out, rtol, atol, error_estimate, method
        namelist /cables/ stiffness, damping
        namelist /chart/ x, x_min, x_max, nx, y, y_min, y_max, ny
        namelist /output/ columns
        integer :: u, ios, k
        integer(int64) :: fsize
        character(len=512) :: msg
        character(len=:), allocatable :: seen
        logical :: halting(size(ieee_usual))

        stat%code = STATUS_OK
        d%path = path
        d%name = deck_name(path)
        title = d%title
        analyses = d%analyses
        model = d%model
        b = d%b
        b_prime = d%b_prime
        l = d%l
        l_prime = d%l_prime
        g = d%g
        mass = d%mass
        inertia = d%inertia
        r = d%r
        lambda = d%lambda
        btilde = d%btilde
        sway_depth = d%sway_depth
        mode = d%mode
        amplitude = d%amplitude
        tilt = d%tilt
        theta = d%theta
        theta_dot = d%theta_dot
        tau_end = d%tau_end
        dtau_out = d%dtau_out
        rtol = d%rtol
        atol = d%atol
        error_estimate = d%error_estimate
        method = d%method
        stiffness = d%cable_stiffness
        damping = d%cable_damping
        fq_amplitude = d%floquet_amplitude
        fq_segments = d%floquet_segments
        fq_rtol = d%floquet_rtol
        x = d%chart_x
        x_min = d%chart_x_min
        x_max = d%chart_x_max
        nx = d%chart_nx
        y = d%chart_y
        y_min = d%chart_y_min
        y_max = d%chart_y_max
        ny = d%chart_ny
        columns = d%columns

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
            call set_error(stat, ERR_DECK, 'cannot open the deck: '//trim(msg))
            return
        end if

        call check_group_names(u, stat, seen)
        if (stat%code == STATUS_OK) then
            ! Values such as 1e400 overflow inside the run-time library: read without traps,
            ! the finiteness checks below catch the result.
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
            ! the newer groups are read only when check_group_names saw them start a group
            ! (a deck without them pays no scan)
            if (index(seen, ' damping ') > 0) call read_group('damping', .false., SPEC_DAMPING)
            if (index(seen, ' measurement ') > 0) &
                call read_group('measurement', .false., SPEC_MEASUREMENT)
            call traps_restore(halting)
        end if
        close (u, iostat=ios)
        if (stat%code /= STATUS_OK) return

        ! &scene: strings are checked here, before they are shortened into d
        do k = 1, len(analyses)
            if (analyses(k:k) == achar(9)) analyses(k:k) = ' '
        end do
        analyses = adjustl(analyses)
        call check_word(stat, 'scene', 'model', model, MODELS_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_analyses(stat, analyses)
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'start', 'mode', mode, 'raised angles')
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'integration', 'method', method, METHODS_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'chart', 'x', x, CHART_VARIABLES)
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'chart', 'y', y, CHART_VARIABLES)
        if (stat%code /= STATUS_OK) return
        call check_columns(stat, columns, d%columns)
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'measurement', 'quantity', d%quantity, QUANTITIES_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_estimate(stat, d%estimate)
        if (stat%code /= STATUS_OK) return
        d%quantity = lower(adjustl(d%quantity))
        d%record_path = ''
        if (len_trim(d%record) > 0) d%record_path = record_in_folder(path, d%record)
        d%title = title
        d%analyses = lower(adjustl(analyses))
        d%model = lower(adjustl(model))
        d%mode = lower(adjustl(mode))
        d%b = b
        d%b_prime = b_prime
        d%l = l
        d%l_prime = l_prime
        d%g = g
        d%mass = mass
        d%inertia = inertia
        d%r = r
        d%lambda = lambda
        d%btilde = btilde
        d%sway_depth = sway_depth
        d%amplitude = amplitude
        d%tilt = tilt
        d%theta = theta
        d%theta_dot = theta_dot
        d%tau_end = tau_end
        d%dtau_out = dtau_out
        d%rtol = rtol
        d%atol = atol
        d%error_estimate = error_estimate
        d%method = lower(adjustl(method))
        d%cable_stiffness = stiffness
        d%cable_damping = damping
        d%floquet_amplitude = fq_amplitude
        d%floquet_segments = fq_segments
        d%floquet_rtol = fq_rtol
        d%chart_x = lower(adjustl(x))
        d%chart_x_min = x_min
        d%chart_x_max = x_max
        d%chart_nx = nx
        d%chart_y = lower(adjustl(y))
        d%chart_y_min = y_min
        d%chart_y_max = y_max
        d%chart_ny = ny
        call check_suspension(d, stat)
        call check_body(d, stat)
        call check_start(d, stat)
        call check_integration(d, stat)
        call check_cables(d, stat)
        call check_floquet(d, stat)
        call check_chart(d, stat)
        if (analysis_requested(d, 'design')) call check_design(d, stat)
        call check_damping(d, stat)
        call check_measurement(d, stat)
        if (stat%code == STATUS_OK) call reduce_angles(d)

    contains

        !> Read one group (if present) and explain any failure.
        subroutine read_group(grp, required, spec)
            character(len=*), intent(in) :: grp         !! group name
            logical, intent(in) :: required            !! absence is an error
            character(len=*), intent(in) :: spec        !! variables, see SPEC_*
            logical :: found, complete
            character(len=:), allocatable :: text, why
            integer, allocatable :: breaks(:)
            integer :: ios2
            character(len=512) :: msg2

            if (stat%code /= STATUS_OK) return
            call scan_group(u, grp, found, complete, text, breaks, ios2, msg2)
            if (ios2 > 0) then
                call set_error(stat, ERR_DECK, 'cannot read the deck: '//trim(msg2))
                return
            end if
            if (.not. found) then
                if (required) call set_error(stat, ERR_DECK, '&'//grp// &
                    ' group missing; it is required (a deck needs &suspension and &body)')
                return
            end if
            ! what the run-time library cannot be trusted with never reaches it
            why = subscript_problem(text, breaks)
            if (len(why) == 0) why = long_text(text)
            if (len(why) > 0) then
                call set_error(stat, ERR_DECK, 'cannot read namelist group &'//grp//': '//why)
                return
            end if
            rewind (u)
            msg2 = ''
            select case (grp)
            case ('scene')
                read (u, nml=scene, iostat=ios2, iomsg=msg2)
            case ('suspension')
                read (u, nml=suspension, iostat=ios2, iomsg=msg2)
            case ('body')
                read (u, nml=body, iostat=ios2, iomsg=msg2)
            case ('start')
                read (u, nml=start, iostat=ios2, iomsg=msg2)
            case ('integration')
                read (u, nml=integration, iostat=ios2, iomsg=msg2)
            case ('cables')
                read (u, nml=cables, iostat=ios2, iomsg=msg2)
            case ('floquet')
                call read_floquet(u, fq_amplitude, fq_segments, fq_rtol, ios2, msg2)
            case ('output')
                read (u, nml=output, iostat=ios2, iomsg=msg2)
            case ('design')
                call read_design(u, d, ios2, msg2)
            case ('damping')
                call read_damping(u, d, ios2, msg2)
            case ('measurement')
                call read_measurement(u, d, ios2, msg2)
            case default
                read (u, nml=chart, iostat=ios2, iomsg=msg2)
            end select
            ! The run-time library reports end of file after the closing '/' of a group on
            ! the last line when that line has no newline; the group itself was read.
            if (ios2 == 0 .or. (is_iostat_end(ios2) .and. complete)) return
            if (.not. complete) then
                call set_error(stat, ERR_DECK, 'cannot read namelist group &'//grp// &
                    ': no closing ''/'' before the end of the file (truncated deck?)')
                return
            end if
            why = explain(text, grp, spec)
            if (len(why) > 0) then
                call set_error(stat, ERR_DECK, 'cannot read namelist group &'//grp// &
                               ': '//why//' (reader: '//trim(msg2)//')')
            else
                call set_error(stat, ERR_DECK, 'cannot read namelist group &'//grp// &
                               ': '//trim(msg2))
            end if
        end subroutine read_group

    end subroutine read_deck

    !> Read &floquet from the rewound unit u; its variables amplitude and rtol have the
    !! names of &start and &integration variables, hence a namelist of its own here.
    subroutine read_floquet(u, amp, segs, rt, ios, msg)
        integer, intent(in) :: u                    !! open deck, rewound
        real(dp), intent(inout) :: amp              !! amplitude: in default, out as read
        integer, intent(inout) :: segs              !! segments: in default, out as read
        real(dp), intent(inout) :: rt               !! rtol: in default, out as read
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: amplitude, rtol
        integer :: segments
        namelist /floquet/ amplitude, segments, rtol
        amplitude = amp
        segments = segs
        rtol = rt
        read (u, nml=floquet, iostat=ios, iomsg=msg)
        amp = amplitude
        segs = segments
        rt = rtol
    end subroutine read_floquet

    !> Read &design from the rewound unit u into d's design_* values (their defaults in,
    !! the values read out); a namelist of its own keeps its names apart from read_deck's.
    subroutine read_design(u, d, ios, msg)
        integer, intent(in) :: u                    !! open deck, rewound
        type(deck_t), intent(inout) :: d            !! design_* values: defaults in, read out
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: l_min, l_max, b_min, b_max, amplitude_max, u_mass, u_l, u_b, u_period
        integer :: nl, nb, n_amplitudes
        namelist /design/ l_min, l_max, nl, b_min, b_max, nb, amplitude_max, n_amplitudes, &
            u_mass, u_l, u_b, u_period
        l_min = d%design_l_min
        l_max = d%design_l_max
        nl = d%design_nl
        b_min = d%design_b_min
        b_max = d%design_b_max
        nb = d%design_nb
        amplitude_max = d%design_amplitude_max
        n_amplitudes = d%design_n_amplitudes
        u_mass = d%design_u_mass
        u_l = d%design_u_l
        u_b = d%design_u_b
        u_period = d%design_u_period
        read (u, nml=design, iostat=ios, iomsg=msg)
        d%design_l_min = l_min
        d%design_l_max = l_max
        d%design_nl = nl
        d%design_b_min = b_min
        d%design_b_max = b_max
        d%design_nb = nb
        d%design_amplitude_max = amplitude_max
        d%design_n_amplitudes = n_amplitudes
        d%design_u_mass = u_mass
        d%design_u_l = u_l
        d%design_u_b = u_b
        d%design_u_period = u_period
    end subroutine read_design
    !> Read &damping from the rewound unit u into d (its name is also a variable of
    !! &cables, hence a namelist of its own here).
    subroutine read_damping(u, d, ios, msg)
        integer, intent(in) :: u                    !! open deck, rewound
        type(deck_t), intent(inout) :: d            !! c_v, c_q: in defaults, out as read
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: c_v, c_q
        namelist /damping/ c_v, c_q
        c_v = d%c_v
        c_q = d%c_q
        read (u, nml=damping, iostat=ios, iomsg=msg)
        d%c_v = c_v
        d%c_q = c_q
    end subroutine read_damping

    !> Read &measurement from the rewound unit u into d; n_periods counts the leading
    !! periods given (check_measurement refuses gaps).
    subroutine read_measurement(u, d, ios, msg)
        integer, intent(in) :: u                    !! open deck, rewound
        type(deck_t), intent(inout) :: d            !! in defaults, out as read
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: periods(MAX_PERIODS), amplitudes(MAX_PERIODS)
        character(len=256) :: record, quantity, estimate     ! values: at most 256 characters
        real(dp) :: u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude
        integer :: monte_carlo, seed
        namelist /measurement/ periods, amplitudes, record, quantity, estimate, u_mass, u_l, &
            u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude, monte_carlo, seed
        periods = d%periods
        amplitudes = d%amplitudes
        record = d%record
        quantity = d%quantity
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
        read (u, nml=measurement, iostat=ios, iomsg=msg)
        d%periods = periods
        d%amplitudes = amplitudes
        d%record = record
        d%quantity = quantity
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
        call put('# &suspension b = '//rshort(d%b)//', b_prime = '//rshort(d%b_prime)// &
                 ', l = '//rshort(d%l)//', l_prime = '//rshort(d%l_prime)//', g = '// &
                 rshort(d%g)//' /')
        line = '# &body mass = '//rshort(d%mass)//', inertia = '//rlist_short(d%inertia)// &
            ', r = '//rshort(d%r)//', lambda = '//rshort(d%lambda)
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
                 ', error_estimate = '//line//', method = '//quoted(d%method)//' /')
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
            rshort(d%design_b_max)//', nb = '//itoa(d%design_nb)//', amplitude_max = '// &
            rshort(d%design_amplitude_max)//', n_amplitudes = '//itoa(d%design_n_amplitudes)// &
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
            call put(line//' estimate = '//quoted(d%estimate)//', u_mass = '// &
                     rshort(d%u_mass)//', u_l = '//rshort(d%u_l)//', u_l_prime = '// &
                     rshort(d%u_l_prime)//', u_b = '//rshort(d%u_b)//', u_b_prime = '// &
                     rshort(d%u_b_prime)//', u_g = '//rshort(d%u_g)//', u_period = '// &
                     rshort(d%u_period)//', u_amplitude = '//rshort(d%u_amplitude)// &
                     ', monte_carlo = '//itoa(d%monte_carlo)//', seed = '//itoa(d%seed)//' /')
        end if

    contains

        subroutine put(text)
            character(len=*), intent(in) :: text
            if (ios == 0) write (unit, '(a)', iostat=ios) text
        end subroutine put

    end subroutine deck_echo

    ! ---------------------------------------------------------------- validation
    ! One routine per group, each checking the values of its group (the defaults are in
    ! deck_t); the first problem sets stat and the later routines return at once.

    !> &suspension: all lengths and g finite, > 0 and within DIM_MIN .. DIM_MAX; b, l, l'
    !! over b' within RATIO_MIN .. RATIO_MAX.
    subroutine check_suspension(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        if (stat%code /= STATUS_OK) return
        call positive(stat, 'suspension', 'b', d%b, 'lengths > 0')
        call positive(stat, 'suspension', 'b_prime', d%b_prime, 'lengths > 0')
        call positive(stat, 'suspension', 'l', d%l, 'lengths > 0')
        call positive(stat, 'suspension', 'l_prime', d%l_prime, 'lengths > 0')
        call positive(stat, 'suspension', 'g', d%g, 'g > 0')
        call dimensional(stat, 'suspension', 'b_prime', d%b_prime)
        call dimensional(stat, 'suspension', 'b', d%b)
        call dimensional(stat, 'suspension', 'l', d%l)
        call dimensional(stat, 'suspension', 'l_prime', d%l_prime)
        call dimensional(stat, 'suspension', 'g', d%g)
        call over_b_prime(stat, 'suspension', 'b', d%b, d%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'suspension', 'l', d%l, d%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'suspension', 'l_prime', d%l_prime, d%b_prime, RATIO_MIN)
    end subroutine check_suspension

    !> &body: mass > 0; principal moments > 0 obeying the triangle inequalities; r >= 0;
    !! btilde a right-handed orthonormal matrix; everything finite.
    subroutine check_body(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        real(dp) :: t(3), half(3), slack, mmt(3,3), det, err, lr
        integer :: i, j, iw, jw
        character(len=*), parameter :: TRI_NAMES(3) = ['I1', 'I2', 'I3']
        if (stat%code /= STATUS_OK) return
        call positive(stat, 'body', 'mass', d%mass, 'mass > 0')
        do i = 1, 3
            call finite(stat, 'body', 'inertia', d%inertia(i))
        end do
        if (stat%code /= STATUS_OK) return
        if (any(d%inertia <= 0.0_dp)) then
            call bad(stat, 'body', 'inertia', rlist_short(d%inertia), &
                     'a principal moment of inertia is <= 0', 'all three > 0')
            return
        end if
        call dimensional(stat, 'body', 'mass', d%mass)
        do i = 1, 3
            call dimensional(stat, 'body', 'inertia', d%inertia(i))
        end do
        if (stat%code /= STATUS_OK) return
        ! I/(m b'^2) in logarithms: the quotient itself may overflow
        do i = 1, 3
            lr = log(d%inertia(i)) - log(d%mass) - 2.0_dp*log(d%b_prime)
            if (lr < log(INERTIA_MIN) .or. lr > log(INERTIA_MAX)) then
                call bad(stat, 'body', 'inertia', rlist_short(d%inertia), TRI_NAMES(i)// &
                         '/(mass b_prime^2) = '//sci(exp(max(-700.0_dp, min(700.0_dp, lr))))// &
                         ' out of range (mass = '//rshort(d%mass)//', b_prime = '// &
                         rshort(d%b_prime)//')', rshort(INERTIA_MIN)//' <= I/(mass b_prime^2)'// &
                         ' <= '//rshort(INERTIA_MAX)//' for each principal moment')
                return
            end if
        end do
        ! triangle inequalities, in halves so that nothing overflows
        half = 0.5_dp*d%inertia
        slack = TRIANGLE_SLACK*maxval(half)
        do i = 1, 3
            t = half
            t(i) = 0.0_dp
            if (half(i) - t(1) - t(2) - t(3) > slack) then
                j = modulo(i, 3) + 1
                call bad(stat, 'body', 'inertia', rlist_short(d%inertia), TRI_NAMES(i)// &
                         ' > '//TRI_NAMES(j)//' + '//TRI_NAMES(modulo(j, 3) + 1)// &
                         ' violates the triangle inequality', &
                         'each principal moment <= the sum of the other two')
                return
            end if
        end do
        call finite(stat, 'body', 'r', d%r)
        call finite(stat, 'body', 'lambda', d%lambda)
        if (stat%code /= STATUS_OK) return
        if (d%r < 0.0_dp) then
            call bad(stat, 'body', 'r', rshort(d%r), 'negative distance', 'r >= 0')
            return
        end if
        if (d%r > 0.0_dp) call over_b_prime(stat, 'body', 'r', d%r, d%b_prime, 0.0_dp)
        call angle(stat, 'body', 'lambda', d%lambda)
        if (stat%code /= STATUS_OK) return
        do i = 1, 3
            do j = 1, 3
                call finite(stat, 'body', 'btilde('//achar(iachar('0') + i)//','// &
                            achar(iachar('0') + j)//')', d%btilde(i, j))
            end do
        end do
        if (stat%code /= STATUS_OK) return
        if (any(abs(d%btilde) > 1.0_dp + ORTHO_TOL)) then
            call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'an element ' // &
                     'exceeds 1 in magnitude, rows are not orthonormal', ortho_allowed())
            return
        end if
        mmt = matmul(d%btilde, transpose(d%btilde))
        err = -1.0_dp
        iw = 0
        jw = 0
        do j = 1, 3
            do i = 1, j
                if (i == j) then
                    if (abs(mmt(i, j) - 1.0_dp) > err) then
                        err = abs(mmt(i, j) - 1.0_dp)
                        iw = i
                        jw = j
                    end if
                else if (abs(mmt(i, j)) > err) then
                    err = abs(mmt(i, j))
                    iw = i
                    jw = j
                end if
            end do
        end do
        if (err > ORTHO_TOL) then
            if (iw == jw) then
                call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'row '// &
                         achar(iachar('0') + iw)//' is not a unit vector (length^2 = '// &
                         rshort(mmt(iw, iw))//')', ortho_allowed())
            else
                call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'rows '// &
                         achar(iachar('0') + iw)//' and '//achar(iachar('0') + jw)// &
                         ' are not orthogonal (dot product = '//rshort(mmt(iw, jw))//')', &
                         ortho_allowed())
            end if
            return
        end if
        det = d%btilde(1, 1)*(d%btilde(2, 2)*d%btilde(3, 3) - d%btilde(2, 3)*d%btilde(3, 2)) &
            - d%btilde(1, 2)*(d%btilde(2, 1)*d%btilde(3, 3) - d%btilde(2, 3)*d%btilde(3, 1)) &
            + d%btilde(1, 3)*(d%btilde(2, 1)*d%btilde(3, 2) - d%btilde(2, 2)*d%btilde(3, 1))
        if (det < 0.0_dp) then
            call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'left-handed ' // &
                     '(determinant = '//rshort(det)//')', 'a right-handed orthonormal ' // &
                     'matrix, determinant +1; change the sign of one row')
            return
        end if
        call finite(stat, 'body', 'sway_depth', d%sway_depth)
        if (stat%code /= STATUS_OK) return
        if (d%sway_depth /= 0.0_dp) call over_b_prime(stat, 'body', 'sway_depth', &
                                                       d%sway_depth, d%b_prime, 0.0_dp)
    end subroutine check_body

    !> &start: finite values; for mode 'raised' 0 < amplitude < 180 degrees; |angles| at most
    !! ANGLE_MAX (they are reduced modulo 2 pi by reduce_angles), |rates| at most RATE_MAX.
    subroutine check_start(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        integer :: i
        if (stat%code /= STATUS_OK) return
        call finite(stat, 'start', 'amplitude', d%amplitude)
        call finite(stat, 'start', 'tilt', d%tilt)
        do i = 1, 4
            call finite(stat, 'start', 'theta', d%theta(i))
            call finite(stat, 'start', 'theta_dot', d%theta_dot(i))
        end do
        if (stat%code /= STATUS_OK) return
        call angle(stat, 'start', 'tilt', d%tilt)
        do i = 1, 4
            call angle(stat, 'start', 'theta', d%theta(i))
        end do
        do i = 1, 4
            if (abs(d%theta_dot(i)) > RATE_MAX) call bad(stat, 'start', 'theta_dot', &
                rlist_short(d%theta_dot), 'a rate beyond '//rshort(RATE_MAX)// &
                ' rad per unit tau', '|theta_dot| <= '//rshort(RATE_MAX)// &
                ' (rad per unit tau; the natural frequencies are of order 1)')
        end do
        if (stat%code /= STATUS_OK) return
        if (trim(d%mode) == 'raised') then
            if (d%amplitude <= 0.0_dp .or. d%amplitude >= 180.0_dp) then
                call bad(stat, 'start', 'amplitude', rshort(d%amplitude), &
                         'out of range for mode ''raised''', '0 < amplitude < 180 (degrees)')
            end if
        end if
    end subroutine check_start

    !> &integration: 0 < dtau_out <= tau_end, at most MAX_ROWS rows, tolerances in range.
    subroutine check_integration(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        if (stat%code /= STATUS_OK) return
        call positive(stat, 'integration', 'tau_end', d%tau_end, 'tau_end > 0')
        call positive(stat, 'integration', 'dtau_out', d%dtau_out, '0 < dtau_out <= tau_end')
        call finite(stat, 'integration', 'rtol', d%rtol)
        call finite(stat, 'integration', 'atol', d%atol)
        if (stat%code /= STATUS_OK) return
        if (d%tau_end > TAU_END_MAX) then
            call bad(stat, 'integration', 'tau_end', rshort(d%tau_end), 'too long a run', &
                     '0 < tau_end <= '//rshort(TAU_END_MAX)//' (units of tau)')
            return
        end if
        if (d%dtau_out > d%tau_end) then
            call bad(stat, 'integration', 'dtau_out', rshort(d%dtau_out), &
                     'larger than tau_end = '//rshort(d%tau_end), '0 < dtau_out <= tau_end')
            return
        end if
        if (d%tau_end/MAX_ROWS > d%dtau_out) then
            call bad(stat, 'integration', 'dtau_out', rshort(d%dtau_out), 'too many ' // &
                     'output rows (tau_end/dtau_out > '//rshort(MAX_ROWS)//', tau_end = '// &
                     rshort(d%tau_end)//')', 'tau_end/dtau_out <= '//rshort(MAX_ROWS)// &
                     ' (the row limit, about 40 MB of .dat)')
            return
        end if
        if (d%rtol < RTOL_MIN .or. d%rtol >= 1.0_dp) then
            call bad(stat, 'integration', 'rtol', rshort(d%rtol), 'relative tolerance ' // &
                     'out of range', '1e-14 <= rtol < 1 (smallest allowed 1e-14)')
            return
        end if
        if (d%atol <= 0.0_dp) then
            call bad(stat, 'integration', 'atol', rshort(d%atol), 'absolute tolerance ' // &
                     'must be > 0', 'atol > 0')
            return
        end if
        ! below ATOL_MIN the integrator's error weights overflow on a state component at 0
        if (d%atol < ATOL_MIN .or. d%atol > ATOL_MAX) then
            call bad(stat, 'integration', 'atol', rshort(d%atol), 'absolute tolerance ' // &
                     'out of range', '1e-30 <= atol <= 1 (radians and rad per unit tau)')
        end if
    end subroutine check_integration

    !> &cables (read and checked whatever the model, used by model = 'elastic').
    subroutine check_cables(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        if (stat%code /= STATUS_OK) return
        call finite(stat, 'cables', 'stiffness', d%cable_stiffness)
        call finite(stat, 'cables', 'damping', d%cable_damping)
        if (stat%code /= STATUS_OK) return
        if (d%cable_stiffness < STIFFNESS_MIN .or. d%cable_stiffness > STIFFNESS_MAX) then
            call bad(stat, 'cables', 'stiffness', rshort(d%cable_stiffness), &
                     'axial stiffness EA/(m g) out of range', '1 <= stiffness <= 1e12')
            return
        end if
        if (d%cable_damping < 0.0_dp .or. d%cable_damping > DAMPING_MAX) then
            call bad(stat, 'cables', 'damping', rshort(d%cable_damping), &
                     'damping ratio out of range', '0 <= damping <= 10 (fraction of critical)')
        end if
    end subroutine check_cables

    !> &damping: c_v, c_q finite and >= 0, each at most DAMPING_SCALED_MAX in the model's
    !! scaled units (c_v / (m b' sqrt(g b')), c_q / (m b'^2)).
    subroutine check_damping(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        if (stat%code /= STATUS_OK) return
        call one('c_v', d%c_v, log(d%mass) + 1.5_dp*log(d%b_prime) + 0.5_dp*log(d%g), &
                 'c_v/(mass b_prime sqrt(g b_prime))')
        call one('c_q', d%c_q, log(d%mass) + 2.0_dp*log(d%b_prime), 'c_q/(mass b_prime^2)')
    contains
        subroutine one(var, x, lscale, scaled)
            character(len=*), intent(in) :: var, scaled
            real(dp), intent(in) :: x               !! the coefficient (deck units)
            real(dp), intent(in) :: lscale          !! log of its scale
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'damping', var, x)
            if (stat%code /= STATUS_OK) return
            if (x < 0.0_dp) then
                call bad(stat, 'damping', var, rshort(x), 'negative damping feeds energy '// &
                         'into the swing', var//' >= 0 (deck units: torque per rate'// &
                         trim(merge(' squared', '        ', var == 'c_q'))//')')
            else if (x > 0.0_dp) then
                if (log(x) - lscale > log(DAMPING_SCALED_MAX)) call bad(stat, 'damping', var, &
                    rshort(x), scaled//' = '//sci(exp(min(700.0_dp, log(x) - lscale)))// &
                    ' out of range', scaled//' <= '//rshort(DAMPING_SCALED_MAX)// &
                    ' (critical damping of torsion is of order 1 in these units)')
            end if
        end subroutine one
    end subroutine check_damping

    !> &measurement: periods given without gaps, each finite, > 0 and at most DIM_MAX, one
    !! amplitude (0 < a < 180 degrees) per period and no more; uncertainties finite, >= 0
    !! and at most DIM_MAX; 0 or 2 .. MAX_MONTE_CARLO Monte Carlo samples.  (quantity and
    !! estimate are checked by read_deck; what identify needs of them, by identify_ready.)
    subroutine check_measurement(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        integer :: i, na
        character(len=16) :: nm
        if (stat%code /= STATUS_OK) return
        do i = d%n_periods + 1, MAX_PERIODS
            if (d%periods(i) /= PERIOD_UNSET) then
                call bad(stat, 'measurement', 'periods('//itoa(i)//')', rshort(d%periods(i)), &
                         'given after a period left out (periods('//itoa(d%n_periods + 1)// &
                         '))', 'periods(1), periods(2), ... without gaps, at most '// &
                         itoa(MAX_PERIODS))
                return
            end if
        end do
        na = 0
        do while (na < MAX_PERIODS)
            if (d%amplitudes(na + 1) == PERIOD_UNSET) exit
            na = na + 1
        end do
        do i = na + 1, MAX_PERIODS
            if (d%amplitudes(i) /= PERIOD_UNSET) then
                call bad(stat, 'measurement', 'amplitudes('//itoa(i)//')', &
                         rshort(d%amplitudes(i)), 'given after an amplitude left out '// &
                         '(amplitudes('//itoa(na + 1)//'))', 'one amplitude per period, '// &
                         'without gaps')
                return
            end if
        end do
        if (na /= d%n_periods) then
            call bad(stat, 'measurement', 'amplitudes', itoa(na)//' values', 'there are '// &
                     itoa(d%n_periods)//' periods', 'one amplitude (degrees of theta4 at the '// &
                     'peak) per period')
            return
        end if
        do i = 1, d%n_periods
            nm = 'periods('//itoa(i)//')'
            call positive(stat, 'measurement', trim(nm), d%periods(i), 'periods > 0 (s)')
            call dimensional(stat, 'measurement', trim(nm), d%periods(i))
            nm = 'amplitudes('//itoa(i)//')'
            call finite(stat, 'measurement', trim(nm), d%amplitudes(i))
            if (stat%code /= STATUS_OK) return
            if (d%amplitudes(i) <= 0.0_dp .or. d%amplitudes(i) >= 180.0_dp) then
                call bad(stat, 'measurement', trim(nm), rshort(d%amplitudes(i)), &
                         'out of range', '0 < amplitude < 180 (degrees of theta4 at the peak)')
                return
            end if
        end do
        call uncertainty('u_mass', d%u_mass)
        call uncertainty('u_l', d%u_l)
        call uncertainty('u_l_prime', d%u_l_prime)
        call uncertainty('u_b', d%u_b)
        call uncertainty('u_b_prime', d%u_b_prime)
        call uncertainty('u_g', d%u_g)
        call uncertainty('u_period', d%u_period)
        call uncertainty('u_amplitude', d%u_amplitude)
        if (stat%code /= STATUS_OK) return
        if (d%monte_carlo == 1 .or. d%monte_carlo < 0 .or. d%monte_carlo > MAX_MONTE_CARLO) &
            call bad(stat, 'measurement', 'monte_carlo', itoa(d%monte_carlo), &
                     'number of Monte Carlo samples out of range', '0 (first order only) '// &
                     'or 2 <= monte_carlo <= '//itoa(MAX_MONTE_CARLO))
    contains
        subroutine uncertainty(var, x)
            character(len=*), intent(in) :: var
            real(dp), intent(in) :: x
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'measurement', var, x)
            if (stat%code /= STATUS_OK) return
            if (x < 0.0_dp .or. x > DIM_MAX) call bad(stat, 'measurement', var, rshort(x), &
                'a standard uncertainty out of range', '0 <= '//var//' <= '// &
                rshort(DIM_MAX)//' (deck units; 0: not known)')
        end subroutine uncertainty
    end subroutine check_measurement

    !> &measurement estimate: blank-separated words from ESTIMATES_ALLOWED (I1 in any case,
    !! the others in lower case too), at least one, none twice.
    subroutine check_estimate(stat, estimate)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: estimate    !! value read
        character(len=len(estimate)) :: list
        integer :: i1, i2, n
        character(len=:), allocatable :: head, allowed, seen
        list = lower(estimate)
        do i1 = 1, len(list)
            if (list(i1:i1) == achar(9)) list(i1:i1) = ' '
        end do
        head = '&measurement estimate = '''//clip(trim(adjustl(estimate)))//''': '
        allowed = 'allowed: blank-separated words from: '//commas(ESTIMATES_ALLOWED)
        seen = ' '
        n = 0
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            n = n + 1
            if (index(' '//lower(ESTIMATES_ALLOWED)//' ', ' '//list(i1:i2)//' ') == 0) then
                call set_error(stat, ERR_DECK, head//'unknown word '''//clip(list(i1:i2))// &
                               '''; '//allowed)
                return
            end if
            if (index(seen, ' '//list(i1:i2)//' ') > 0) then
                call set_error(stat, ERR_DECK, head//''''//list(i1:i2)//''' given twice; '// &
                               allowed)
                return
            end if
            seen = seen//list(i1:i2)//' '
        end do
        if (n == 0) call set_error(stat, ERR_DECK, head//'no parameter given; '//allowed)
    end subroutine check_estimate

    !> True when the blank-separated word `word` (e.g. 'c_q') is in &measurement estimate.
    logical function estimated(d, word)
        type(deck_t), intent(in) :: d               !! the deck
        character(len=*), intent(in) :: word        !! one of ESTIMATES_ALLOWED
        estimated = index(' '//lower(d%estimate)//' ', ' '//lower(trim(word))//' ') > 0
    end function estimated

    !> &floquet: 0 < amplitude < 180 degrees, 1..MAX_SEGMENTS segments, rtol in range.
    subroutine check_floquet(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        if (stat%code /= STATUS_OK) return
        call finite(stat, 'floquet', 'amplitude', d%floquet_amplitude)
        call finite(stat, 'floquet', 'rtol', d%floquet_rtol)
        if (stat%code /= STATUS_OK) return
        if (d%floquet_amplitude < FLOQUET_AMPLITUDE_MIN .or. d%floquet_amplitude >= 180.0_dp) then
            call bad(stat, 'floquet', 'amplitude', rshort(d%floquet_amplitude), &
                     'out of range', rshort(FLOQUET_AMPLITUDE_MIN)//' <= amplitude < 180 '// &
                     '(degrees of theta4)')
            return
        end if
        if (d%floquet_segments < 1 .or. d%floquet_segments > MAX_SEGMENTS) then
            call bad(stat, 'floquet', 'segments', itoa(d%floquet_segments), &
                     'number of shooting segments out of range', '1 <= segments <= '// &
                     itoa(MAX_SEGMENTS))
            return
        end if
        if (d%floquet_rtol < RTOL_MIN .or. d%floquet_rtol >= FLOQUET_RTOL_MAX) then
            call bad(stat, 'floquet', 'rtol', rshort(d%floquet_rtol), &
                     'relative tolerance out of range', '1e-14 <= rtol < 1e-2')
        end if
    end subroutine check_floquet

    !> &chart: two different variables (known words, checked by read_deck), each axis a
    !! finite range inside its variable's range with 2..MAX_CHART_N points, nx*ny bounded.
    subroutine check_chart(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        if (stat%code /= STATUS_OK) return
        if (trim(d%chart_x) == trim(d%chart_y)) then
            call bad(stat, 'chart', 'y', quoted(d%chart_y), 'the same variable as x', &
                     'y different from x, both from: '//commas(CHART_VARIABLES))
            return
        end if
        call chart_axis('x', d%chart_x, d%chart_x_min, d%chart_x_max, d%chart_nx)
        call chart_axis('y', d%chart_y, d%chart_y_min, d%chart_y_max, d%chart_ny)
        if (stat%code /= STATUS_OK) return
        if (d%chart_nx*d%chart_ny > MAX_CHART_POINTS) then
            call bad(stat, 'chart', 'ny', itoa(d%chart_ny), 'too many chart points ' // &
                     '(nx*ny = '//itoa(d%chart_nx*d%chart_ny)//', nx = '//itoa(d%chart_nx)// &
                     ')', 'nx*ny <= '//itoa(MAX_CHART_POINTS))
        end if

    contains

        !> One chart axis: finite min < max inside the range of its variable, 2..1000 points.
        subroutine chart_axis(ax, var, vmin, vmax, n)
            character(len=*), intent(in) :: ax      !! 'x' or 'y'
            character(len=*), intent(in) :: var     !! chart variable, lower case
            real(dp), intent(in) :: vmin, vmax      !! range
            integer, intent(in) :: n                !! number of points
            real(dp) :: lo, hi
            logical :: lo_in, hi_in
            character(len=:), allocatable :: desc, allowed
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'chart', ax//'_min', vmin)
            call finite(stat, 'chart', ax//'_max', vmax)
            if (stat%code /= STATUS_OK) return
            if (vmin >= vmax) then
                call bad(stat, 'chart', ax//'_max', rshort(vmax), 'not larger than '// &
                         ax//'_min = '//rshort(vmin), ax//'_min < '//ax//'_max')
                return
            end if
            ! allowed range lo .. hi of the variable, ends included when lo_in, hi_in
            lo = 0.0_dp
            hi = huge(1.0_dp)
            lo_in = .false.
            hi_in = .true.
            select case (trim(var))
            case ('l')
                desc = 'cable length l''/b'''
                lo = RATIO_MIN
                hi = RATIO_MAX
                lo_in = .true.
            case ('b')
                desc = 'b/b'''
                lo = RATIO_MIN
                hi = RATIO_MAX
                lo_in = .true.
            case ('amplitude')
                desc = 'degrees'
                lo = FLOQUET_AMPLITUDE_MIN
                lo_in = .true.
                hi = 180.0_dp
                hi_in = .false.
            case ('r')
                desc = 'r/b'''
                hi = RATIO_MAX
                lo_in = .true.
            case ('lambda')
                desc = 'radians, -pi/2 .. pi/2'
                lo = -PI_HALF
                hi = PI_HALF
                lo_in = .true.
            case default
                desc = 'I3/I1'
                hi = RATIO_MAX
            end select
            allowed = rshort(lo)//trim(merge(' <=', ' < ', lo_in))//' '//ax//'_min < '// &
                ax//'_max'
            if (hi < huge(1.0_dp)) allowed = allowed//trim(merge(' <=', ' < ', hi_in))//' '// &
                rshort(hi)
            allowed = allowed//' for '//trim(var)//' ('//desc//')'
            if (vmin < lo .or. (vmin == lo .and. .not. lo_in)) then
                call bad(stat, 'chart', ax//'_min', rshort(vmin), 'outside the ' // &
                         'range of '//trim(var), allowed)
                return
            end if
            if (vmax > hi .or. (vmax == hi .and. .not. hi_in)) then
                call bad(stat, 'chart', ax//'_max', rshort(vmax), 'outside the ' // &
                         'range of '//trim(var), allowed)
                return
            end if
            if (n < 2 .or. n > MAX_CHART_N) then
                call bad(stat, 'chart', 'n'//ax, itoa(n), 'number of chart points ' // &
                         'out of range', '2 <= n'//ax//' <= '//itoa(MAX_CHART_N)// &
                         ' and nx*ny <= '//itoa(MAX_CHART_POINTS))
                return
            end if
        end subroutine chart_axis

    end subroutine check_chart

    !> &design (checked when the analysis is requested; its lengths are in deck units):
    !! finite values; 0 < l_min < l_max with l over b' in RATIO_MIN .. RATIO_MAX and
    !! 2 <= nl <= MAX_CHART_N; b kept (b_min = b_max = 0, nb = 1), one b (b_min = b_max > 0,
    !! nb = 1) or 0 < b_min < b_max with 2 <= nb <= MAX_CHART_N, b over b' in range;
    !! 0 < amplitude_max <= 90 degrees, 1 <= n_amplitudes <= MAX_DESIGN_AMPLITUDES, the
    !! smallest amplitude amplitude_max/n_amplitudes >= FLOQUET_AMPLITUDE_MIN; at most
    !! MAX_CHART_POINTS Floquet points; each uncertainty >= 0 and below the value it
    !! qualifies (u_mass < mass, u_l < l_min, u_b below every b and b'; the period is only
    !! known when computed: the analysis checks u_period against it).
    subroutine check_design(d, stat)
        type(deck_t), intent(in) :: d               !! deck with the values read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        real(dp) :: bmin
        if (stat%code /= STATUS_OK) return
        call positive(stat, 'design', 'l_min', d%design_l_min, '0 < l_min < l_max (deck units)')
        call positive(stat, 'design', 'l_max', d%design_l_max, '0 < l_min < l_max (deck units)')
        if (stat%code /= STATUS_OK) return
        if (d%design_l_min >= d%design_l_max) then
            call bad(stat, 'design', 'l_max', rshort(d%design_l_max), 'not larger than '// &
                     'l_min = '//rshort(d%design_l_min), 'l_min < l_max')
            return
        end if
        call over_b_prime(stat, 'design', 'l_min', d%design_l_min, d%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'design', 'l_max', d%design_l_max, d%b_prime, RATIO_MIN)
        if (stat%code /= STATUS_OK) return
        if (d%design_nl < 2 .or. d%design_nl > MAX_CHART_N) then
            call bad(stat, 'design', 'nl', itoa(d%design_nl), 'number of cable lengths '// &
                     'out of range', '2 <= nl <= '//itoa(MAX_CHART_N))
            return
        end if
        call finite(stat, 'design', 'b_min', d%design_b_min)
        call finite(stat, 'design', 'b_max', d%design_b_max)
        if (stat%code /= STATUS_OK) return
        if (d%design_nb == 1) then
            if (d%design_b_min /= d%design_b_max) then
                call bad(stat, 'design', 'b_max', rshort(d%design_b_max), 'differs from '// &
                         'b_min = '//rshort(d%design_b_min)//' with nb = 1', 'b_min = '// &
                         'b_max = 0 with nb = 1 (the deck''s b), b_min = b_max > 0 with '// &
                         'nb = 1 (that b), or 0 < b_min < b_max with nb >= 2')
                return
            end if
            if (d%design_b_min /= 0.0_dp) call positive(stat, 'design', 'b_min', &
                d%design_b_min, 'b_min = b_max = 0 (the deck''s b) or > 0')
        else if (d%design_nb < 1 .or. d%design_nb > MAX_CHART_N) then
            call bad(stat, 'design', 'nb', itoa(d%design_nb), 'number of support spacings '// &
                     'out of range', '1 <= nb <= '//itoa(MAX_CHART_N))
            return
        else
            call positive(stat, 'design', 'b_min', d%design_b_min, '0 < b_min < b_max '// &
                          'with nb >= 2')
            if (stat%code /= STATUS_OK) return
            if (d%design_b_min >= d%design_b_max) call bad(stat, 'design', 'b_max', &
                rshort(d%design_b_max), 'not larger than b_min = '//rshort(d%design_b_min)// &
                ' with nb = '//itoa(d%design_nb), 'b_min < b_max with nb >= 2')
        end if
        if (stat%code /= STATUS_OK) return
        if (d%design_b_min > 0.0_dp) then
            call over_b_prime(stat, 'design', 'b_min', d%design_b_min, d%b_prime, RATIO_MIN)
            call over_b_prime(stat, 'design', 'b_max', d%design_b_max, d%b_prime, RATIO_MIN)
        end if
        call finite(stat, 'design', 'amplitude_max', d%design_amplitude_max)
        if (stat%code /= STATUS_OK) return
        if (d%design_amplitude_max <= 0.0_dp .or. d%design_amplitude_max > 90.0_dp) then
            call bad(stat, 'design', 'amplitude_max', rshort(d%design_amplitude_max), &
                     'out of range', '0 < amplitude_max <= 90 (degrees of theta4)')
            return
        end if
        if (d%design_n_amplitudes < 1 .or. d%design_n_amplitudes > MAX_DESIGN_AMPLITUDES) then
            call bad(stat, 'design', 'n_amplitudes', itoa(d%design_n_amplitudes), &
                     'number of amplitudes out of range', '1 <= n_amplitudes <= '// &
                     itoa(MAX_DESIGN_AMPLITUDES))
            return
        end if
        if (d%design_amplitude_max/d%design_n_amplitudes < FLOQUET_AMPLITUDE_MIN) then
            call bad(stat, 'design', 'amplitude_max', rshort(d%design_amplitude_max), &
                     'its smallest amplitude amplitude_max/n_amplitudes is below '// &
                     rshort(FLOQUET_AMPLITUDE_MIN)//' degrees', 'amplitude_max/n_amplitudes'// &
                     ' >= '//rshort(FLOQUET_AMPLITUDE_MIN)//' (degrees of theta4)')
            return
        end if
        if (real(d%design_nl, dp)*d%design_nb*d%design_n_amplitudes > MAX_CHART_POINTS) then
            call bad(stat, 'design', 'n_amplitudes', itoa(d%design_n_amplitudes), &
                     'too many Floquet points (nl*nb*n_amplitudes = '// &
                     sci(real(d%design_nl, dp)*d%design_nb*d%design_n_amplitudes)//')', &
                     'nl*nb*n_amplitudes <= '//itoa(MAX_CHART_POINTS))
            return
        end if
        bmin = min(d%b_prime, d%b)
        if (d%design_b_min > 0.0_dp) bmin = min(d%b_prime, d%design_b_min)
        call uncertainty('u_mass', d%design_u_mass, d%mass, 'the mass')
        call uncertainty('u_l', d%design_u_l, d%design_l_min, 'l_min')
        call uncertainty('u_b', d%design_u_b, bmin, 'every b and b_prime')
        call uncertainty('u_period', d%design_u_period, huge(1.0_dp), '')

    contains

        !> A standard uncertainty: finite, >= 0, below the value it qualifies.
        subroutine uncertainty(var, u, x, what)
            character(len=*), intent(in) :: var     !! its name
            real(dp), intent(in) :: u, x            !! the uncertainty and its value
            character(len=*), intent(in) :: what    !! the value's name ('' for none)
            character(len=:), allocatable :: allowed
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'design', var, u)
            if (stat%code /= STATUS_OK) return
            allowed = '0 <= '//var
            if (len(what) > 0) allowed = allowed//' < '//what//' ('//rshort(x)//')'
            allowed = allowed//', a standard uncertainty in deck units'
            if (var == 'u_period') allowed = allowed//' (s)'
            if (u < 0.0_dp) then
                call bad(stat, 'design', var, rshort(u), 'a negative uncertainty', allowed)
            else if (len(what) > 0 .and. u >= x) then
                call bad(stat, 'design', var, rshort(u), 'not below the value it qualifies', &
                         allowed)
            end if
        end subroutine uncertainty

    end subroutine check_design

    !> ERR_DECK naming the deck, group, variable and value, what is wrong and what is
    !! allowed (nothing when stat already carries an error).
    subroutine bad(stat, grp, var, val, what, allowed)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var, val, what, allowed
        if (stat%code /= STATUS_OK) return
        call set_error(stat, ERR_DECK, '&'//grp//' '//var//' = '//val//': '// &
                       what//'; allowed: '//allowed)
    end subroutine bad

    !> ERR_DECK when x is NaN or infinite.
    subroutine finite(stat, grp, var, x)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x
        if (.not. ieee_is_finite(x)) call bad(stat, grp, var, rshort(x), 'not a finite ' &
                                              //'number (NaN, Inf, or beyond 1.8e308)', &
                                              'finite real numbers')
    end subroutine finite

    !> ERR_DECK when the dimensional value x (> 0) lies outside DIM_MIN .. DIM_MAX.
    subroutine dimensional(stat, grp, var, x)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x                   !! a length, g, a mass or a moment (> 0)
        if (stat%code /= STATUS_OK) return          ! x may be NaN
        if (x < DIM_MIN .or. x > DIM_MAX) call bad(stat, grp, var, rshort(x), 'out of ' // &
            'range', rshort(DIM_MIN)//' <= '//var//' <= '//rshort(DIM_MAX)//' in any units')
    end subroutine dimensional

    !> ERR_DECK when |x|/b' (x /= 0, b' > 0, both finite) lies outside lo .. RATIO_MAX
    !! (lo = 0: no lower bound).
    subroutine over_b_prime(stat, grp, var, x, b_prime, lo)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x, b_prime          !! the length (/= 0) and b' (> 0)
        real(dp), intent(in) :: lo                  !! smallest ratio allowed (0: none)
        real(dp) :: lq
        character(len=:), allocatable :: allowed, nm
        if (stat%code /= STATUS_OK) return
        nm = var
        if (x < 0.0_dp .or. var == 'sway_depth') nm = '|'//var//'|'     ! a signed length
        lq = log(abs(x)) - log(b_prime)   ! in logarithms: x/b' itself may overflow
        if (lq <= log(RATIO_MAX)) then
            if (lo <= 0.0_dp) return
            if (lq >= log(lo)) return
        end if
        allowed = nm//'/b_prime <= '//rshort(RATIO_MAX)
        if (lo > 0.0_dp) allowed = rshort(lo)//' <= '//allowed
        call bad(stat, grp, var, rshort(x), nm//'/b_prime = '// &
                 sci(exp(max(-700.0_dp, min(700.0_dp, lq))))//' out of range (b_prime = '// &
                 rshort(b_prime)//')', allowed//' (the geometry in units of b_prime)')
    end subroutine over_b_prime

    !> ERR_DECK when an angle (rad) is beyond ANGLE_MAX in magnitude.
    subroutine angle(stat, grp, var, x)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x                   !! angle, rad (finite)
        if (stat%code /= STATUS_OK) return
        if (abs(x) > ANGLE_MAX) call bad(stat, grp, var, rshort(x), 'an angle beyond '// &
            rshort(ANGLE_MAX)//' rad', '|'//var//'| <= '//rshort(ANGLE_MAX)// &
            ' rad (angles are taken modulo 2 pi)')
    end subroutine angle

    !> The deck's angles (tilt, theta, lambda; |x| <= ANGLE_MAX) reduced modulo 2 pi into
    !! [-pi, pi]: the integrator's error control is relative, so an angle of 1e6 rad would
    !! leave it a tolerance of rtol*1e6 rad.
    subroutine reduce_angles(d)
        type(deck_t), intent(inout) :: d            !! deck after the checks
        d%tilt = reduced(d%tilt)
        d%theta = [reduced(d%theta(1)), reduced(d%theta(2)), reduced(d%theta(3)), &
                   reduced(d%theta(4))]
        d%lambda = reduced(d%lambda)
    end subroutine reduce_angles

    !> x - 2 pi n, n the nearest integer to x/(2 pi), with 2 pi split in three parts
    !! (Cody and Waite) so that the result is accurate to roundoff for |x| <= 2**20 * 2 pi;
    !! x itself when |x| <= pi.
    pure real(dp) function reduced(x) result(r)
        real(dp), intent(in) :: x                   !! angle, rad
        real(dp), parameter :: TWO_PI = 6.283185307179586_dp
        ! 2 pi = P1 + P2 + P3: P1 with 33 significant bits (n*P1 exact for n < 2**20), P2 the
        ! rest of the double TWO_PI, P3 = 2 pi - TWO_PI
        real(dp), parameter :: P1 = real(int(TWO_PI*2.0_dp**30, int64), dp)/2.0_dp**30
        real(dp), parameter :: P2 = TWO_PI - P1
        real(dp), parameter :: P3 = 2.4492935982947064e-16_dp
        real(dp) :: n
        r = x
        if (abs(x) <= 0.5_dp*TWO_PI) return
        n = anint(x/TWO_PI)
        r = ((x - n*P1) - n*P2) - n*P3
    end function reduced

    !> ERR_DECK when x is not finite or not > 0.
    subroutine positive(stat, grp, var, x, allowed)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var, allowed
        real(dp), intent(in) :: x
        if (stat%code /= STATUS_OK) return
        call finite(stat, grp, var, x)
        if (stat%code /= STATUS_OK) return
        if (x <= 0.0_dp) call bad(stat, grp, var, rshort(x), 'must be > 0', allowed)
    end subroutine positive

    pure function ortho_allowed() result(s)
        character(len=:), allocatable :: s
        s = 'orthonormal rows within 1e-9 (btilde btilde^T = I) and determinant +1'
    end function ortho_allowed

    !> Check that a string value is one of the blank-separated words of `allowed`.
    subroutine check_word(stat, grp, var, val, allowed)
        type(status_t), intent(inout) :: stat       !! ERR_DECK when val is not allowed
        character(len=*), intent(in) :: grp, var, val, allowed
        if (index(' '//allowed//' ', ' '//lower(trim(adjustl(val)))//' ') > 0 .and. &
            len_trim(val) > 0 .and. index(trim(adjustl(val)), ' ') == 0) return
        call set_error(stat, ERR_DECK, '&'//grp//' '//var//' = '''//clip(trim(val))// &
                       ''': unknown '//var//'; allowed: '//commas(allowed))
    end subroutine check_word

    !> &output columns: blank-separated names from OUTPUT_COLUMNS (any case), at least one,
    !! none twice; `cols` gets them in OUTPUT_COLUMNS' order, with its spelling.
    subroutine check_columns(stat, columns, cols)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: columns     !! value read
        character(len=*), intent(inout) :: cols     !! the columns, in OUTPUT_COLUMNS' order
        character(len=len(columns)) :: list
        character(len=len(OUTPUT_COLUMNS)) :: known
        logical :: asked(count_words(OUTPUT_COLUMNS))
        integer :: i1, i2, j1, j2, n
        character(len=:), allocatable :: head, allowed
        list = columns
        do i1 = 1, len(list)
            if (list(i1:i1) == achar(9)) list(i1:i1) = ' '
        end do
        known = lower(OUTPUT_COLUMNS)
        head = '&output columns = '''//trim(adjustl(list))//''': '
        allowed = 'allowed: blank-separated names, in any order and case, from: '// &
            commas(OUTPUT_COLUMNS)
        asked = .false.
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            j2 = 0
            n = 0
            do
                call next_word(known, j2, j1)
                if (j1 == 0) exit
                n = n + 1
                if (known(j1:j2) == lower(list(i1:i2))) exit
            end do
            if (j1 == 0) then
                call set_error(stat, ERR_DECK, head//'unknown column '''//list(i1:i2)// &
                               '''; '//allowed)
                return
            end if
            if (asked(n)) then
                call set_error(stat, ERR_DECK, head//'column '''//list(i1:i2)// &
                               ''' given twice; '//allowed)
                return
            end if
            asked(n) = .true.
        end do
        if (.not. any(asked)) then
            call set_error(stat, ERR_DECK, head//'no column given; '//allowed)
            return
        end if
        cols = ''
        j2 = 0
        n = 0
        do
            call next_word(OUTPUT_COLUMNS, j2, j1)
            if (j1 == 0) exit
            n = n + 1
            if (asked(n)) cols = trim(cols)//' '//OUTPUT_COLUMNS(j1:j2)
        end do
        cols = adjustl(cols)
    end subroutine check_columns

    !> Number of blank-separated words in s.
    pure integer function count_words(s) result(n)
        character(len=*), intent(in) :: s
        integer :: i1, i2
        n = 0
        i2 = 0
        do
            call next_word(s, i2, i1)
            if (i1 == 0) exit
            n = n + 1
        end do
    end function count_words

    !> Every word of &scene analyses must be known; at least one word.
    subroutine check_analyses(stat, analyses)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: analyses    !! value read
        character(len=len(analyses)) :: list
        integer :: i1, i2
        character(len=:), allocatable :: head
        list = lower(analyses)
        head = '&scene analyses = '''//clip(trim(analyses))//''': '
        if (len_trim(list) > 256) then
            call set_error(stat, ERR_DECK, head//'longer than 256 characters; allowed: '// &
                           'blank-separated words from: '//commas(ANALYSES_ALLOWED))
            return
        end if
        if (len_trim(list) == 0) then
            call set_error(stat, ERR_DECK, head//'no analysis given; allowed: '// &
                           'blank-separated words from: '//commas(ANALYSES_ALLOWED))
            return
        end if
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            if (index(' '//ANALYSES_ALLOWED//' ', ' '//list(i1:i2)//' ') == 0) then
                call set_error(stat, ERR_DECK, head//'unknown analysis '''// &
                               analyses(i1:i2)//'''; allowed: blank-separated words from: '// &
                               commas(ANALYSES_ALLOWED))
                return
            end if
        end do
    end subroutine check_analyses

    ! ---------------------------------------------------------------- file scanning

    !> Every '&name' that starts a group must be a known group; the deck must not be empty,
    !! no line longer than MAX_LINE characters, the whole deck not larger than MAX_DECK_BYTES.
    !! `seen` lists the groups that start somewhere (' name name ... ', lower case).
    subroutine check_group_names(u, stat, seen)
        integer, intent(in) :: u                    !! open deck
        type(status_t), intent(inout) :: stat       !! ERR_DECK on an unknown group
        character(len=:), allocatable, intent(out) :: seen  !! the groups seen
        character(len=:), allocatable :: line
        integer :: ios, i, j, nlines
        integer(int64) :: nbytes
        character(len=512) :: msg
        rewind (u)
        seen = ' '
        nlines = 0
        nbytes = 0
        do
            call read_line(u, line, ios, msg)
            if (ios > 0) then
                call set_error(stat, ERR_DECK, 'cannot read the deck: '//trim(msg))
                return
            end if
            if (ios < 0) exit
            nlines = nlines + 1
            nbytes = nbytes + len(line) + 1
            if (len(line) > MAX_LINE) then
                call set_error(stat, ERR_DECK, 'line '//itoa(nlines)//' is longer than '// &
                               itoa(MAX_LINE)//' characters; allowed: lines of at most '// &
                               itoa(MAX_LINE)//' characters (a title holds 256)')
                return
            end if
            if (nbytes > MAX_DECK_BYTES) then
                call set_error(stat, ERR_DECK, 'the deck is larger than '// &
                               itoa(MAX_DECK_BYTES)//' bytes; allowed: decks of at most '// &
                               itoa(MAX_DECK_BYTES)//' bytes')
                return
            end if
            i = index(line, '!')
            if (i > 0) line = line(1:i - 1)
            do i = 1, len(line) - 1
                if (line(i:i) /= '&') cycle
                if (i > 1) then
                    if (line(i - 1:i - 1) /= ' ' .and. line(i - 1:i - 1) /= '/' .and. &
                        line(i - 1:i - 1) /= achar(9)) cycle
                end if
                j = i + 1
                do while (j <= len(line))
                    if (.not. is_ident(line(j:j))) exit
                    j = j + 1
                end do
                if (j == i + 1) cycle
                if (lower(line(i + 1:j - 1)) == 'end') cycle
                if (index(' '//GROUPS_ALLOWED//' ', ' '//lower(line(i + 1:j - 1))//' ') == 0) then
                    call set_error(stat, ERR_DECK, 'unknown namelist group &'// &
                                   clip(line(i + 1:j - 1))//'; allowed: &'// &
                                   commas(GROUPS_ALLOWED, ', &'))
                    return
                end if
                if (index(seen, ' '//lower(line(i + 1:j - 1))//' ') == 0) &
                    seen = seen//lower(line(i + 1:j - 1))//' '
            end do
        end do
        if (nlines == 0) then
            call set_error(stat, ERR_DECK, 'the deck is empty or not a regular file; '// &
                           'allowed: a namelist file with &suspension and &body')
            return
        end if
        rewind (u)
    end subroutine check_group_names

    !> Find the first '&grp' outside comments and collect its text up to the closing '/'
    !! (outside quotes), comments removed, lines joined by blanks.  Linear in the deck's
    !! size.  `breaks` lists the positions in text where a line ended.
    subroutine scan_group(u, grp, found, complete, text, breaks, ios, msg)
        integer, intent(in) :: u                    !! open deck
        character(len=*), intent(in) :: grp         !! group name
        logical, intent(out) :: found               !! the group starts somewhere
        logical, intent(out) :: complete            !! its closing '/' was found
        character(len=:), allocatable, intent(out) :: text    !! the group's items
        integer, allocatable, intent(out) :: breaks(:)        !! text(breaks(k)) ends a line
        integer, intent(out) :: ios                 !! > 0 when the file cannot be read
        character(len=*), intent(inout) :: msg      !! message for ios > 0
        character(len=:), allocatable :: line, buf
        integer, allocatable :: brk(:)
        character :: q
        integer :: i, n, i0, nt, nb
        found = .false.
        complete = .false.
        q = ' '
        nt = 0
        nb = 0
        allocate (character(len=256) :: buf)
        allocate (brk(16))
        rewind (u)
        do
            call read_line(u, line, ios, msg)
            if (ios > 0) exit
            if (ios < 0) then
                ios = 0
                exit
            end if
            i = 1
            if (.not. found) then
                ! look for &grp, as the run-time library does (no quotes outside a group)
                n = len(grp)
                do i = 1, len(line)
                    if (q == ' ' .and. line(i:i) == '!') exit
                    if (line(i:i) /= '&' .or. i + n > len(line)) cycle
                    if (lower(line(i + 1:i + n)) /= grp) cycle
                    if (i + n < len(line)) then
                        if (is_ident(line(i + n + 1:i + n + 1))) cycle
                    end if
                    found = .true.
                    exit
                end do
                if (.not. found) cycle
                i = i + n + 1
            end if
            i0 = i
            do while (i <= len(line))
                if (q /= ' ') then
                    if (line(i:i) == q) q = ' '
                else if (line(i:i) == '!') then
                    exit
                else if (line(i:i) == '''' .or. line(i:i) == '"') then
                    q = line(i:i)
                else if (line(i:i) == '/') then
                    complete = .true.
                    exit
                end if
                i = i + 1
            end do
            call append(line(i0:i - 1)//' ')
            if (complete) exit
            nb = nb + 1
            if (nb > size(brk)) brk = [brk, brk]
            brk(nb) = nt
        end do
        text = buf(1:nt)
        breaks = brk(1:nb)

    contains

        !> Append s to buf(1:nt), doubling its length when full.
        subroutine append(s)
            character(len=*), intent(in) :: s
            character(len=:), allocatable :: grown
            if (nt + len(s) > len(buf)) then
                allocate (character(len=2*(nt + len(s))) :: grown)
                grown(1:nt) = buf(1:nt)
                call move_alloc(grown, buf)
            end if
            buf(nt + 1:nt + len(s)) = s
            nt = nt + len(s)
        end subroutine append

    end subroutine scan_group

    !> Read one whole line of any length (tabs and carriage returns as blanks), in time linear
    !! in its length; reading stops after max_len + 1 characters (default MAX_LINE; the
    !! caller refuses such a line), so a file without newlines (/dev/zero) ends at once.
    subroutine read_line(u, line, ios, msg, max_len)
        integer, intent(in) :: u                    !! open unit
        character(len=:), allocatable, intent(out) :: line   !! the line, without newline
        integer, intent(out) :: ios                 !! 0, < 0 at end of file, > 0 on error
        character(len=*), intent(inout) :: msg      !! message for ios > 0
        integer, intent(in), optional :: max_len    !! longest line the caller accepts
        character(len=1024) :: chunk
        character(len=:), allocatable :: buf, grown
        integer :: n, nl, nmax
        nmax = MAX_LINE
        if (present(max_len)) nmax = max_len
        allocate (character(len=1024) :: buf)
        nl = 0
        do
            n = 0
            read (u, '(a)', advance='no', size=n, iostat=ios, iomsg=msg) chunk
            if (nl + n > len(buf)) then
                allocate (character(len=2*(nl + n)) :: grown)
                grown(1:nl) = buf(1:nl)
                call move_alloc(grown, buf)
            end if
            buf(nl + 1:nl + n) = chunk(1:n)
            nl = nl + n
            if (is_iostat_eor(ios)) then
                ios = 0
                exit
            end if
            if (is_iostat_end(ios) .and. nl > 0) then
                ios = 0
                exit
            end if
            if (ios /= 0) exit
            if (nl > nmax) exit
        end do
        line = buf(1:nl)
        do n = 1, nl
            if (line(n:n) == achar(9) .or. line(n:n) == achar(13)) line(n:n) = ' '
        end do
    end subroutine read_line

    !> A value longer than MAX_TEXT characters, quoted or not ('' when none): the run-time
    !! library would cut it to its variable's length (and the checking build prints a
    !! warning); no number needs as many digits.
    function long_text(text) result(why)
        character(len=*), intent(in) :: text        !! group items (from scan_group)
        character(len=:), allocatable :: why
        character :: q
        integer :: k, k0, n
        why = ''
        q = ' '
        n = 0
        k0 = 1
        do k = 1, len(text)
            if (q == ' ') then
                if (text(k:k) == '''' .or. text(k:k) == '"') then
                    q = text(k:k)
                    n = 0
                    k0 = k
                    cycle
                else if (index(' ,=', text(k:k)) > 0) then
                    n = 0
                    k0 = k + 1
                    cycle
                end if
            else if (text(k:k) == q) then
                q = ' '      ! a doubled quote closes and reopens: counted as two values
                n = 0
                cycle
            end if
            n = n + 1
            if (n > MAX_TEXT) then
                why = 'a value of more than '//itoa(MAX_TEXT)//' characters ('// &
                    clip(text(k0:))//'); allowed: at most '//itoa(MAX_TEXT)
                return
            end if
        end do
    end function long_text

    !> The first parenthesis of a group's text that the run-time library cannot be trusted
    !! with (gfortran 12 takes SIGSEGV on a subscript left open at the end of a line): every
    !! '(' outside quotes must follow a variable name, close on the same line, and hold only
    !! digits, blanks, '+', '-', ':' and ','.  Empty when all are well formed.
    function subscript_problem(text, breaks) result(why)
        character(len=*), intent(in) :: text        !! group items (from scan_group)
        integer, intent(in) :: breaks(:)            !! line ends in text (from scan_group)
        character(len=:), allocatable :: why
        character :: q
        integer :: k, j, b, e, nextb
        why = ''
        q = ' '
        b = 1
        k = 0
        do while (k < len(text))
            k = k + 1
            if (q /= ' ') then
                if (text(k:k) == q) q = ' '
                cycle
            end if
            if (text(k:k) == '''' .or. text(k:k) == '"') then
                q = text(k:k)
                cycle
            end if
            if (text(k:k) == ')') then
                why = 'unexpected '')'' in '''//clip(item_at(k))//''''
                return
            end if
            if (text(k:k) /= '(') cycle
            ! the variable name before '('
            j = k - 1
            do while (j >= 1)
                if (text(j:j) /= ' ') exit
                j = j - 1
            end do
            if (j < 1) then
                why = 'unexpected ''('' in '''//clip(item_at(k))//'''; subscripts follow a '// &
                      'variable name, e.g. inertia(1) = 0.1'
                return
            end if
            if (.not. is_ident(text(j:j))) then
                why = 'unexpected ''('' in '''//clip(item_at(k))//'''; subscripts follow a '// &
                      'variable name, e.g. inertia(1) = 0.1, and values have no parentheses'
                return
            end if
            do while (b <= size(breaks))
                if (breaks(b) >= k) exit
                b = b + 1
            end do
            nextb = len(text)
            if (b <= size(breaks)) nextb = breaks(b)
            e = index(text(k + 1:nextb), ')')
            if (e == 0) then
                why = 'subscript '''//clip(item_at(k))//''' not closed on its line; '// &
                      'allowed: a subscript on one line, e.g. btilde(1,:) = 1, 0, 0'
                return
            end if
            e = k + e
            do while (j > 1)
                if (.not. is_ident(text(j - 1:j - 1))) exit
                j = j - 1
            end do
            if (verify(text(k + 1:e - 1), '0123456789+-:, ') /= 0 .or. &
                len_trim(text(k + 1:e - 1)) == 0) then
                why = 'bad subscript '''//clip(text(j:e))//'''; allowed: integers, '':'' '// &
                      'and '','', e.g. inertia(2) or btilde(1,:)'
                return
            end if
            k = e
        end do

    contains

        !> The line of text that holds position p.
        function item_at(p) result(s)
            integer, intent(in) :: p
            character(len=:), allocatable :: s
            integer :: i1, i2, bb
            i1 = 1
            i2 = len(text)
            do bb = 1, size(breaks)
                if (breaks(bb) >= p) then
                    i2 = breaks(bb)
                    exit
                end if
                i1 = breaks(bb) + 1
            end do
            s = trim(adjustl(text(i1:i2)))
        end function item_at

    end function subscript_problem

    !> Explain why the run-time library could not read a group: the first item whose name is
    !! unknown, whose value has the wrong form, or which has too many values.  Empty when no
    !! explanation is found.
    function explain(text, grp, spec) result(why)
        character(len=*), intent(in) :: text        !! group items (from scan_group)
        character(len=*), intent(in) :: grp         !! group name
        character(len=*), intent(in) :: spec        !! variables, see SPEC_*
        character(len=:), allocatable :: why
        integer :: neq, k, j, depth, p1, v1, v2, t1, t2, nval, cnt, star, ios
        integer, allocatable :: eqs(:), nstart(:), nend(:)
        logical :: subscripted
        character :: q, kind
        character(len=:), allocatable :: nm, tok, val, names, lhs
        integer :: vsize

        why = ''
        allocate (eqs(count([(text(k:k) == '=', k = 1, len(text))])))
        neq = 0
        q = ' '
        do k = 1, len(text)
            if (q /= ' ') then
                if (text(k:k) == q) q = ' '
            else if (text(k:k) == '''' .or. text(k:k) == '"') then
                q = text(k:k)
            else if (text(k:k) == '=') then
                neq = neq + 1
                eqs(neq) = k
            end if
        end do
        names = spec_names(spec)
        q = ' '
        do k = 1, len(text) - 1
            if (q /= ' ') then
                if (text(k:k) == q) q = ' '
            else if (text(k:k) == '''' .or. text(k:k) == '"') then
                q = text(k:k)
            else if (text(k:k) == '&' .and. is_ident(text(k + 1:k + 1))) then
                j = k + 1
                do while (j <= len(text))
                    if (.not. is_ident(text(j:j))) exit
                    j = j + 1
                end do
                why = 'no closing ''/'' before '''//clip(text(k:j - 1))//''''
                return
            end if
        end do
        if (neq == 0) then
            if (len_trim(text) > 0) why = 'expected name = value, found '''// &
                clip(trim(adjustl(text)))//'''; allowed variables: '//names
            return
        end if
        allocate (nstart(neq), nend(neq))
        do k = 1, neq
            j = eqs(k) - 1
            do while (j >= 1)
                if (text(j:j) /= ' ') exit
                j = j - 1
            end do
            if (j >= 1) then
                if (text(j:j) == ')') then
                    depth = 0
                    do while (j >= 1)
                        if (text(j:j) == ')') depth = depth + 1
                        if (text(j:j) == '(') depth = depth - 1
                        if (depth == 0) exit
                        j = j - 1
                    end do
                    j = j - 1
                    do while (j >= 1)
                        if (text(j:j) /= ' ') exit
                        j = j - 1
                    end do
                end if
            end if
            nend(k) = j
            do while (j >= 1)
                if (.not. is_ident(text(j:j))) exit
                j = j - 1
            end do
            nstart(k) = j + 1
            if (nstart(k) > nend(k)) then
                why = 'expected a variable name before ''='' in '''//clip(trim(adjustl(text)))// &
                    '''; allowed variables: '//names
                return
            end if
        end do
        if (len_trim(text(1:nstart(1) - 1)) > 0) then
            why = 'unexpected '''//clip(trim(adjustl(text(1:nstart(1) - 1))))// &
                ''' before the first variable'
            return
        end if
        do k = 1, neq
            nm = lower(text(nstart(k):nend(k)))
            subscripted = eqs(k) > nend(k) + 1
            if (subscripted) subscripted = len_trim(text(nend(k) + 1:eqs(k) - 1)) > 0
            lhs = clip(trim(text(nstart(k):eqs(k) - 1)))
            call spec_lookup(spec, nm, kind, vsize)
            if (kind == ' ') then
                why = 'unknown variable '''//clip(text(nstart(k):nend(k)))//''' in &'//grp// &
                    '; allowed variables: '//names
                return
            end if
            v1 = eqs(k) + 1
            v2 = len(text)
            if (k < neq) v2 = nstart(k + 1) - 1
            val = trim(adjustl(text(v1:v2)))
            if (len(val) > 0) then
                if (val(len(val):len(val)) == ',') val = trim(val(1:len(val) - 1))
            end if
            val = clip(val)
            ! tokens separated by blanks or commas outside quotes
            nval = 0
            p1 = v1
            do
                call next_token(text(1:v2), p1, t1, t2)
                if (t1 == 0) exit
                p1 = t2 + 1
                tok = text(t1:t2)
                cnt = 1
                star = index(tok, '*')
                if (star > 1 .and. tok(1:1) /= '''' .and. tok(1:1) /= '"') then
                    read (tok(1:star - 1), '(i20)', iostat=ios) cnt
                    if (ios /= 0 .or. verify(tok(1:star - 1), '0123456789') /= 0) then
                        cnt = 1
                    else
                        tok = tok(star + 1:)
                    end if
                end if
                nval = nval + cnt
                if (len(tok) == 0) cycle
                if (.not. token_ok(tok, kind)) then
                    select case (kind)
                    case ('r')
                        why = lhs//' = '//val//': '''//clip(tok)// &
                            ''' is not a real number'
                    case ('i')
                        why = lhs//' = '//val//': '''//clip(tok)// &
                            ''' is not an integer'
                    case ('c')
                        why = lhs//' = '//val//': character values '// &
                            'must be quoted, e.g. '//nm//' = ''...'''
                    case default
                        why = lhs//' = '//val//': '''//clip(tok)// &
                            ''' is not a logical; allowed: .true., .false.'
                    end select
                    return
                end if
            end do
            if (.not. subscripted .and. nval > vsize) then
                why = lhs//' = '//val//': too many values for '//nm// &
                    ' (it holds '//itoa(vsize)//')'
                return
            end if
        end do
    end function explain

    !> Next token of s after position p (blanks and commas separate; quotes kept whole).
    subroutine next_token(s, p, t1, t2)
        character(len=*), intent(in) :: s           !! text
        integer, intent(in) :: p                    !! start searching here
        integer, intent(out) :: t1, t2              !! token s(t1:t2); t1 = 0 when none
        integer :: i
        character :: q
        t1 = 0
        t2 = 0
        i = p
        do while (i <= len(s))
            if (s(i:i) /= ' ' .and. s(i:i) /= ',') exit
            i = i + 1
        end do
        if (i > len(s)) return
        t1 = i
        q = ' '
        do while (i <= len(s))
            if (q /= ' ') then
                if (s(i:i) == q) q = ' '
            else if (s(i:i) == '''' .or. s(i:i) == '"') then
                q = s(i:i)
            else if (s(i:i) == ' ' .or. s(i:i) == ',') then
                exit
            end if
            i = i + 1
        end do
        t2 = i - 1
    end subroutine next_token

    !> Whether a value token has the form its kind needs.
    logical function token_ok(tok, kind)
        character(len=*), intent(in) :: tok         !! the token (repeat count removed)
        character, intent(in) :: kind               !! r, i, c or l
        character(len=:), allocatable :: s
        s = lower(tok)
        select case (kind)
        case ('r')
            token_ok = is_real(s)
        case ('i')
            if (s(1:1) == '+' .or. s(1:1) == '-') s = s(2:)
            token_ok = len(s) > 0
            if (token_ok) token_ok = verify(s, '0123456789') == 0
        case ('c')
            token_ok = .false.
            if (len(s) >= 2) token_ok = (s(1:1) == '''' .or. s(1:1) == '"') .and. &
                s(len(s):len(s)) == s(1:1)
        case default
            if (s(1:1) == '.') s = s(2:)
            token_ok = .false.
            if (len(s) > 0) token_ok = s(1:1) == 't' .or. s(1:1) == 'f'
        end select
    end function token_ok

    !> Whether s (lower case) is a Fortran real literal, NaN or Inf.
    logical function is_real(s)
        character(len=*), intent(in) :: s           !! candidate, lower case
        integer :: i, nd
        is_real = .false.
        i = 1
        if (len(s) == 0) return
        if (s(1:1) == '+' .or. s(1:1) == '-') i = 2
        if (i > len(s)) return
        if (s(i:) == 'nan' .or. s(i:) == 'inf' .or. s(i:) == 'infinity') then
            is_real = .true.
            return
        end if
        nd = 0
        do while (i <= len(s))
            if (index('0123456789', s(i:i)) == 0) exit
            nd = nd + 1
            i = i + 1
        end do
        if (i <= len(s)) then
            if (s(i:i) == '.') then
                i = i + 1
                do while (i <= len(s))
                    if (index('0123456789', s(i:i)) == 0) exit
                    nd = nd + 1
                    i = i + 1
                end do
            end if
        end if
        if (nd == 0) return
        if (i > len(s)) then
            is_real = .true.
            return
        end if
        if (index('edq', s(i:i)) > 0) i = i + 1
        if (i <= len(s)) then
            if (s(i:i) == '+' .or. s(i:i) == '-') i = i + 1
        end if
        if (i > len(s)) return
        is_real = verify(s(i:), '0123456789') == 0
    end function is_real

    !> Blank-separated names of a spec, as 'a, b, c'.
    function spec_names(spec) result(s)
        character(len=*), intent(in) :: spec        !! see SPEC_*
        character(len=:), allocatable :: s
        integer :: i1, i2, c
        s = ''
        i2 = 0
        do
            call next_word(spec, i2, i1)
            if (i1 == 0) exit
            c = index(spec(i1:i2), ':')
            if (len(s) > 0) s = s//', '
            s = s//spec(i1:i1 + c - 2)
        end do
    end function spec_names

    !> Kind and size of variable nm in spec; kind = ' ' when unknown.
    subroutine spec_lookup(spec, nm, kind, vsize)
        character(len=*), intent(in) :: spec        !! see SPEC_*
        character(len=*), intent(in) :: nm          !! variable name, lower case
        character, intent(out) :: kind              !! r, i, c, l or blank
        integer, intent(out) :: vsize               !! number of elements
        integer :: i1, i2, c, ios
        kind = ' '
        vsize = 0
        i2 = 0
        do
            call next_word(spec, i2, i1)
            if (i1 == 0) exit
            c = i1 + index(spec(i1:i2), ':') - 1
            if (spec(i1:c - 1) == nm) then
                kind = spec(c + 1:c + 1)
                read (spec(c + 2:i2), *, iostat=ios) vsize
                return
            end if
        end do
    end subroutine spec_lookup

    ! ---------------------------------------------------------------- small helpers

    !> Next blank-separated word of s after position i2: s(i1:i2); i1 = 0 when none.
    pure subroutine next_word(s, i2, i1)
        character(len=*), intent(in) :: s           !! text
        integer, intent(inout) :: i2                !! in: end of previous word; out: end
        integer, intent(out) :: i1                  !! start of the word, 0 when none
        integer :: i
        i1 = 0
        i = i2 + 1
        do while (i <= len(s))
            if (s(i:i) /= ' ') exit
            i = i + 1
        end do
        if (i > len(s)) return
        i1 = i
        do while (i <= len(s))
            if (s(i:i) == ' ') exit
            i = i + 1
        end do
        i2 = i - 1
    end subroutine next_word

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

    pure function lower(s) result(t)
        character(len=*), intent(in) :: s           !! any text
        character(len=len(s)) :: t
        integer :: i
        t = s
        do i = 1, len(s)
            if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') t(i:i) = achar(iachar(s(i:i)) + 32)
        end do
    end function lower

    pure logical function is_ident(c)
        character, intent(in) :: c                  !! one character
        is_ident = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') .or. &
                   (c >= '0' .and. c <= '9') .or. c == '_'
    end function is_ident

    !> 'a b c' -> 'a, b, c' (or another separator).
    pure function commas(words, sep) result(s)
        character(len=*), intent(in) :: words       !! blank-separated words
        character(len=*), intent(in), optional :: sep   !! separator, default ', '
        character(len=:), allocatable :: s
        integer :: i1, i2
        s = ''
        i2 = 0
        do
            call next_word(words, i2, i1)
            if (i1 == 0) exit
            if (len(s) > 0) then
                if (present(sep)) then
                    s = s//sep
                else
                    s = s//', '
                end if
            end if
            s = s//words(i1:i2)
        end do
    end function commas

    !> Shortest real that reads back exactly (for messages): 180, 0.3, 1e-15, 1.7e308.
    function rshort(x) result(s)
        real(dp), intent(in) :: x                   !! value
        character(len=:), allocatable :: s
        character(len=48) :: buf
        integer :: k, ie
        logical :: halting(size(ieee_usual)), fixed
        if (.not. ieee_is_finite(x)) then
            write (buf, '(g0)') x
            s = trim(adjustl(buf))
            return
        end if
        call traps_off(halting)     ! a rounded 1.7e308 reads back as an overflow
        fixed = .false.
        if (x == 0.0_dp .or. (abs(x) >= 1.0e-4_dp .and. abs(x) < 1.0e15_dp)) then
            k = fewest_digits(x, .true.)
            fixed = k >= 0
        end if
        if (fixed) then
            write (buf, '(f48.'//itoa(k)//')') x
            s = lead_zero(buf)
            if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
        else
            k = fewest_digits(x, .false.)
            if (k < 0) k = 16
            write (buf, '(es48.'//itoa(k)//'e3)') x
            s = trim(adjustl(buf))
            ie = index(s, 'E')
            ! 1.E-015 -> 1e-15, 1.7E+308 -> 1.7e308
            k = ie + 2
            do while (k < len(s))
                if (s(k:k) /= '0') exit
                k = k + 1
            end do
            if (s(ie + 1:ie + 1) == '-') then
                s = s(1:ie - 1)//'e-'//s(k:)
            else
                s = s(1:ie - 1)//'e'//s(k:)
            end if
            ie = index(s, '.e')
            if (ie > 0) s = s(1:ie - 1)//s(ie + 1:)
        end if
        call traps_restore(halting)
    end function rshort

    !> The fewest digits after the point, k, with which x written in fixed (f48.k, k <= 24) or
    !! scientific notation (es48.ke3, k <= 16) reads back exactly; -1 when none does.  The
    !! same k as trying k = 0, 1, 2, ... in turn, in about four trials instead of up to 25:
    !! k = 0, then the candidate from x's 16-digit text (its digits without trailing zeros),
    !! then down while a shorter text still reads back.  Where x is not a power of two the
    !! values that read back as x lie symmetrically around it, and a text with one digit more
    !! is never further from x, so the texts that read back are those from the fewest digits
    !! on; powers of two (asymmetric) and surprises take the trials in turn.  Traps off.
    function fewest_digits(x, fixed_form) result(k)
        real(dp), intent(in) :: x                   !! finite value
        logical, intent(in) :: fixed_form           !! f48.k, else es48.ke3
        integer :: k
        character(len=48) :: buf
        integer :: kmax, kc, p, e10, i0, ie, j
        kmax = merge(24, 16, fixed_form)
        k = 0
        if (reads_back(k)) return
        if (abs(fraction(x)) /= 0.5_dp) then
            write (buf, '(es48.15e3)') x
            buf = adjustl(buf)
            i0 = index(buf, '.')
            ie = index(buf, 'E')
            p = 16
            do j = ie - 1, i0 + 1, -1
                if (buf(j:j) /= '0') exit
                p = p - 1
            end do
            e10 = 0
            do j = ie + 2, len_trim(buf)
                e10 = 10*e10 + (iachar(buf(j:j)) - iachar('0'))
            end do
            if (buf(ie + 1:ie + 1) == '-') e10 = -e10
            kc = p - 1
            if (fixed_form) kc = p - 1 - e10
            kc = max(1, kc)
            if (kc <= kmax) then
                if (reads_back(kc)) then
                    do while (kc > 1)
                        if (.not. reads_back(kc - 1)) exit
                        kc = kc - 1
                    end do
                    k = kc
                    return
                end if
            end if
        end if
        do k = 1, kmax
            if (reads_back(k)) return
        end do
        k = -1
    contains
        !> x written with kk digits after the point reads back as x.
        logical function reads_back(kk)
            integer, intent(in) :: kk
            character(len=48) :: txt
            real(dp) :: y
            integer :: ios
            if (fixed_form) then
                write (txt, '(f48.'//itoa(kk)//')') x
            else
                write (txt, '(es48.'//itoa(kk)//'e3)') x
            end if
            read (txt, *, iostat=ios) y
            reads_back = ios == 0 .and. y == x
        end function reads_back
    end function fewest_digits

    !> Stop trapping overflow, division by zero and invalid (when traps are supported),
    !! remembering the halting modes in saved.
    subroutine traps_off(saved)
        logical, intent(out) :: saved(:)            !! halting modes of ieee_usual
        integer :: k
        do k = 1, size(ieee_usual)
            saved(k) = .false.
            if (ieee_support_halting(ieee_usual(k))) then
                call ieee_get_halting_mode(ieee_usual(k), saved(k))
                call ieee_set_halting_mode(ieee_usual(k), .false.)
            end if
        end do
    end subroutine traps_off

    !> Clear the flags raised since traps_off and restore the halting modes.
    subroutine traps_restore(saved)
        logical, intent(in) :: saved(:)             !! from traps_off
        integer :: k
        call ieee_set_flag(ieee_usual, .false.)
        do k = 1, size(ieee_usual)
            if (ieee_support_halting(ieee_usual(k))) &
                call ieee_set_halting_mode(ieee_usual(k), saved(k))
        end do
    end subroutine traps_restore

    function rlist_short(x) result(s)
        real(dp), intent(in) :: x(:)                !! values
        character(len=:), allocatable :: s
        integer :: i
        s = ''
        do i = 1, size(x)
            if (i > 1) s = s//', '
            s = s//rshort(x(i))
        end do
    end function rlist_short

    function btilde_short(bt) result(s)
        real(dp), intent(in) :: bt(3,3)             !! btilde
        character(len=:), allocatable :: s
        s = '['//rlist_short(bt(1, :))//'; '//rlist_short(bt(2, :))//'; '// &
            rlist_short(bt(3, :))//']'
    end function btilde_short

    !> s for a message: at most CLIP_LEN characters, longer text cut with '...'.
    pure function clip(s) result(t)
        character(len=*), intent(in) :: s          !! any text
        character(len=:), allocatable :: t
        if (len(s) <= CLIP_LEN) then
            t = s
        else
            t = s(1:CLIP_LEN - 3)//'...'
        end if
    end function clip

    !> Quoted for namelist output, inner quotes doubled.
    pure function quoted(s) result(t)
        character(len=*), intent(in) :: s           !! text
        character(len=:), allocatable :: t
        integer :: i
        t = ''''
        do i = 1, len_trim(s)
            if (s(i:i) == '''') then
                t = t//''''''
            else
                t = t//s(i:i)
            end if
        end do
        t = t//''''
    end function quoted

end module deck
