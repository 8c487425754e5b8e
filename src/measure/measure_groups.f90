!> The deck's groups of the measurements: &measurement (analysis identify: measured periods,
!! a recorded swing or a table of releases, and the standard uncertainties of the inputs)
!! and &tensor (analysis tensor: the table of hangs and the uncertainties of its inputs).
!! Each is a type extending deck_group_t with its keys and their defaults, its name and
!! spec, its read from the group's text, its echo, its check (submodule measure_checks:
!! intent(in), against the rig's groups) and its normalisation (normalise: words in lower
!! case, the cycles of every period, the quantity implied by record_units, one u_inertia
!! for I2 and I3, the files relative to the deck's folder).
module measure_groups
    use kinds, only: dp
    use status, only: status_t
    use text, only: itoa, rshort, rlist_short, lower, quoted
    use deck_base, only: deck_group_t, NOT_GIVEN, record_in_folder
    use rig_groups, only: suspension_group_t, body_group_t, start_group_t
    implicit none
    private

    !> Most periods in &measurement periods (and amplitudes).
    integer, parameter, public :: MAX_PERIODS = 100
    !> The value of an element of periods, amplitudes, cycles the deck did not give.
    real(dp), parameter, public :: PERIOD_UNSET = -huge(1.0_dp)
    !> The smallest amplitude (degrees) of a timed period the model resolves: below it the
    !! swing is lost in the integration's own error (the Floquet analyses' bound).
    real(dp), parameter, public :: AMPLITUDE_MIN = 1.0e-6_dp
    !> Words allowed in &measurement estimate: the parameters a record fit can estimate.
    !! amplitude_scale: the scale every timed period's amplitude is read on (periods only).
    character(len=*), parameter, public :: ESTIMATES_ALLOWED = 'I1 c_v c_q amplitude t0 bias '// &
        'amplitude_scale I2 I3 cg_depth tilt sway scale'
    !> Words allowed in &measurement record_units (each implies the quantity).
    character(len=*), parameter, public :: RECORD_UNITS_ALLOWED = 'rad deg rad/s deg/s'
    !> Words allowed in &measurement loss.
    character(len=*), parameter, public :: LOSSES_ALLOWED = 'squares huber'
    !> Words allowed in &measurement on_failure: what a release that fails does to the run.
    character(len=*), parameter, public :: ON_FAILURE_ALLOWED = 'stop skip'
    !> Words allowed in &measurement quantity: column 2 of a record.
    character(len=*), parameter, public :: QUANTITIES_ALLOWED = 'angle rate rates point'
    !> Words allowed in &measurement record_view (quantity 'point'): the camera looks up the
    !! vertical (below: the point's horizontal position) or along a horizontal (side).
    character(len=*), parameter, public :: VIEWS_ALLOWED = 'below side'
    public :: check_estimate, parse_axes
    !> Most Monte Carlo samples of &measurement and &tensor monte_carlo.
    integer, parameter :: MAX_MONTE_CARLO = 1000000

    !> &measurement (analysis identify): measured periods or a recorded swing.  Tracked
    !! (gave): quantity, record_columns, u_inertia (its first element), u_inertia(2).
    type, extends(deck_group_t), public :: measurement_group_t
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
        !> the relative standard uncertainty of the scale every amplitude is read on (one
        !! instrument's: a protractor's, a video's): common to every period and release,
        !! entered once, not averaged down; 0 .. 0.5
        real(dp) :: u_amplitude_scale = 0.0_dp
        integer :: monte_carlo = 0                !! Monte Carlo samples (0: first order only)
        integer :: seed = 1                       !! seed of the Monte Carlo streams
        !> each period is the total time of cycles(i) cycles (PERIOD_UNSET: not given, then
        !! 1); one value serves every period (normalise)
        real(dp) :: cycles(MAX_PERIODS) = PERIOD_UNSET
        character(len=256) :: trials = ''         !! a table of releases ('' for none)
        character(len=:), allocatable :: trials_path  !! relative to the deck's folder
        !> the record's columns: time, value and (0: none) each sample's u; -1 in the third:
        !! not given (then 1, 2, or a gyro export's axis with the largest swing; a third
        !! column is each sample's u only when record_columns names it); 0 in the first: no
        !! time column (the row and record_frame_rate give the time), or by name
        !! quantity 'rates': time and the instrument's three axes x, y, z (no u)
        integer :: record_columns(4) = [1, 2, -1, -1]
        !> the columns given by name in the header (lower case), where record_columns is 0
        character(len=256) :: record_column_names(4) = ''
        !> frames a second: the time column holds frame numbers, t = frame/F, or, without
        !! a time column, t = (row - 1)/F; 0: the time column is in s
        real(dp) :: record_frame_rate = 0.0_dp
        character(len=256) :: record_units = ''   !! RECORD_UNITS_ALLOWED ('' : by quantity)
        !> quantity 'rates': the instrument's axes in the body's principal axes: 'aligned'
        !! or three signed letters ('z -y x': the body axes along its x, y, z)
        character(len=256) :: record_axes = 'aligned'
        !> the record holds several releases, each after the body was held still: cut at
        !! its holds (module record_split), each segment a release, pooled as a table's
        logical :: record_split = .false.
        !> quantity 'point': the tracked point in the body's principal axes from the mass
        !! centre (m; PERIOD_UNSET: not given), the camera's view (VIEWS_ALLOWED) and the
        !! record's scale (m per unit of a column, e.g. m/px; 1: the columns are metres)
        real(dp) :: record_point(3) = PERIOD_UNSET
        character(len=256) :: record_view = 'below'
        real(dp) :: record_scale = 1.0_dp
        character(len=256) :: loss = 'squares'    !! LOSSES_ALLOWED: the record fit's loss
        !> standard uncertainties of I2 and I3 (u_inertia(1) alone serves both: normalise),
        !! of the mass centre (as measured: cg_depth, cg_offset; or r (length) and lambda
        !! (rad))
        real(dp) :: u_inertia(2) = 0.0_dp
        real(dp) :: u_cg_depth = 0.0_dp, u_cg_offset = 0.0_dp, u_r = 0.0_dp, u_lambda = 0.0_dp
        !> a fixture measured alone and subtracted (its I1 about the same axis, u, its mass),
        !! and a known added inertia (e.g. entrained air) subtracted
        real(dp) :: tare_i1 = 0.0_dp, u_tare_i1 = 0.0_dp, tare_mass = 0.0_dp
        real(dp) :: added_inertia = 0.0_dp, u_added_inertia = 0.0_dp
        !> ON_FAILURE_ALLOWED: a release that fails stops the run, or is left out (skip)
        character(len=256) :: on_failure = 'stop'
        !> the session of the deck's release (a label; a table's releases without a column
        !! session take it)
        character(len=256) :: session = ''
        !> a rig calibration (NAME.calibration of analysis calibrate; '' for none) and a
        !! tare measured by identify (its NAME.identify; '' for none), as given and
        !! relative to the deck's folder
        character(len=256) :: calibration = '', tare = ''
        character(len=:), allocatable :: calibration_path, tare_path
    contains
        procedure, nopass :: name => measurement_name
        procedure, nopass :: spec => measurement_spec
        procedure :: read_text => read_measurement
        procedure :: echo => echo_measurement
        procedure :: check => check_measurement
        procedure :: normalise => normalise_measurement
        procedure :: estimated
        procedure :: u_inertia_of
    end type measurement_group_t

    !> &tensor (analysis tensor): the table of hangs and the uncertainties of its inputs.
    type, extends(deck_group_t), public :: tensor_group_t
        character(len=256) :: hangs = ''          !! the hangs table as given ('' for none)
        character(len=:), allocatable :: hangs_path     !! relative to the deck's folder
        !> standard uncertainties of mass, l, l_prime, b, b_prime, g, period (s), amplitude
        !! (degrees), deck units
        real(dp) :: u(8) = 0.0_dp
        real(dp) :: u_direction = 0.0_dp          !! of how the body was set in a hang (deg)
        integer :: monte_carlo = 0, seed = 1
        real(dp) :: cg(3) = 0.0_dp                !! the mass centre in the body frame
        logical :: cg_given = .false.
        integer :: plan = 0                       !! hangs to plan (0: none)
        integer :: plan_add = 0                   !! hangs to add to the table (0: none)
        !> a fixture that hung with the body in every hang: its mass, mass centre and
        !! inertia about its mass centre (a 3 x 3 matrix) in the frame fixture_frame
        !! ('body': the table's body frame; 'hang': along CD, across, up from CD's midpoint)
        real(dp) :: fixture_mass = 0.0_dp, fixture_cg(3) = 0.0_dp
        real(dp) :: fixture_inertia(3, 3) = 0.0_dp
        real(dp) :: u_fixture_mass = 0.0_dp, u_fixture_cg(3) = 0.0_dp
        real(dp) :: u_fixture_inertia(3, 3) = 0.0_dp  !! of each entry
        character(len=8) :: fixture_frame = 'body'
        !> what the fit estimates: 'tensor' (the six entries) or 'tensor cg' (and the mass
        !! centre, from the periods and the hangs' attitudes)
        character(len=32) :: estimate = 'tensor'
        real(dp) :: u_attitude = 0.1_dp           !! of a hang's measured attitude (deg)
    contains
        procedure :: has_fixture => tensor_has_fixture
        procedure :: estimates_cg => tensor_estimates_cg
        procedure, nopass :: name => tensor_name
        procedure, nopass :: spec => tensor_spec
        procedure :: read_text => read_tensor
        procedure :: echo => echo_tensor
        procedure :: check => check_tensor
        procedure :: normalise => normalise_tensor
    end type tensor_group_t

    ! ---- submodule measure_checks
    interface
        !> &measurement: periods, amplitudes, record, uncertainties (each inside its input's
        !! domain), Monte Carlo.
        module subroutine check_measurement(self, sus, bod, sta, stat)
            class(measurement_group_t), intent(in) :: self
            type(suspension_group_t), intent(in) :: sus     !! the suspension, normalised
            type(body_group_t), intent(in) :: bod           !! the body as given
            type(start_group_t), intent(in) :: sta          !! the start, normalised
            type(status_t), intent(inout) :: stat
        end subroutine check_measurement
        !> &tensor: the uncertainties, Monte Carlo, the plan, a table of hangs when the
        !! analysis is asked for.
        !> Words of an estimate (&measurement estimate, or a release's column estimate):
        !! from ESTIMATES_ALLOWED, at least one, none twice.  head: the start of the message
        !! ("&measurement estimate = 'WORDS': " when absent).
        module subroutine check_estimate(stat, estimate, head)
            type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
            character(len=*), intent(in) :: estimate    !! value read
            character(len=*), intent(in), optional :: head
        end subroutine check_estimate
        module subroutine check_tensor(self, sus, bod, requested, stat)
            class(tensor_group_t), intent(in) :: self
            type(suspension_group_t), intent(in) :: sus     !! the suspension, normalised
            type(body_group_t), intent(in) :: bod
            logical, intent(in) :: requested                !! analyses = '... tensor ...'
            type(status_t), intent(inout) :: stat
        end subroutine check_tensor
    end interface

contains

    ! ------------------------------------------------------------------ &measurement

    function measurement_name() result(s)
        character(len=:), allocatable :: s
        s = 'measurement'
    end function measurement_name

    function measurement_spec() result(s)
        character(len=:), allocatable :: s
        s = 'periods:r100 amplitudes:r100 record:c1 quantity:c1 estimate:c1 u_mass:r1 '// &
            'u_l:r1 u_l_prime:r1 u_b:r1 u_b_prime:r1 u_g:r1 u_period:r1 u_amplitude:r1 '// &
            'monte_carlo:i1 seed:i1 cycles:r100 trials:c1 record_columns:k4 record_units:c1 '// &
            'loss:c1 u_inertia:r2 u_cg_depth:r1 u_cg_offset:r1 u_r:r1 u_lambda:r1 tare_i1:r1 '// &
            'u_tare_i1:r1 tare_mass:r1 added_inertia:r1 u_added_inertia:r1 '// &
            'on_failure:c1 session:c1 record_frame_rate:r1 calibration:c1 tare:c1 '// &
            'u_amplitude_scale:r1 record_axes:c1 record_split:l1 record_point:r3 '// &
            'record_view:c1 record_scale:r1'
    end function measurement_spec

    !> &measurement; n_periods counts the leading periods given (check refuses gaps).
    !! record_columns is read as numbers (as it was always given) and, when that read fails,
    !! again as text: numbers and names of the header's columns (column_words); one value
    !! alone is the value's column (no time column).
    subroutine read_measurement(self, rec, ios, msg)
        class(measurement_group_t), intent(inout) :: self   !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: periods(MAX_PERIODS), amplitudes(MAX_PERIODS), cycles(MAX_PERIODS)
        character(len=256) :: record, quantity, estimate, trials, record_units, loss
        character(len=256) :: on_failure, session, calibration, tare, record_axes
        character(len=256) :: record_view
        real(dp) :: record_point(3), record_scale
        real(dp) :: u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude
        real(dp) :: u_inertia(2), u_cg_depth, u_cg_offset, u_r, u_lambda
        real(dp) :: tare_i1, u_tare_i1, tare_mass, added_inertia, u_added_inertia
        real(dp) :: record_frame_rate, u_amplitude_scale
        integer :: monte_carlo, seed, record_columns(4), ios_words
        logical :: record_split
        character(len=256) :: words(4), msg_words
        namelist /measurement/ periods, amplitudes, cycles, record, quantity, estimate, u_mass, &
            u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude, monte_carlo, seed, &
            trials, record_columns, record_units, loss, u_inertia, u_cg_depth, u_cg_offset, &
            u_r, u_lambda, tare_i1, u_tare_i1, tare_mass, added_inertia, u_added_inertia, &
            on_failure, session, record_frame_rate, calibration, tare, u_amplitude_scale, &
            record_axes, record_split, record_point, record_view, record_scale
        call defaults()
        words = ''
        read (rec, nml=measurement, iostat=ios, iomsg=msg)
        if (ios /= 0) then
            ! record_columns as text (names of the header's columns)
            call defaults()
            msg_words = ''
            call read_words(ios_words, msg_words)
            if (ios_words == 0) then
                ios = 0
                record_columns = -1
            else
                call defaults()
                words = ''
                read (rec, nml=measurement, iostat=ios, iomsg=msg)
            end if
        end if
        self%periods = periods
        self%amplitudes = amplitudes
        self%cycles = cycles
        self%record = record
        if (len_trim(quantity) > 0) then
            self%quantity = quantity
            call self%note_given('quantity')
        end if
        self%estimate = estimate
        self%u_mass = u_mass
        self%u_l = u_l
        self%u_l_prime = u_l_prime
        self%u_b = u_b
        self%u_b_prime = u_b_prime
        self%u_g = u_g
        self%u_period = u_period
        self%u_amplitude = u_amplitude
        self%u_amplitude_scale = u_amplitude_scale
        self%monte_carlo = monte_carlo
        self%seed = seed
        self%trials = trials
        if (any(words /= '')) then
            call column_words(words, self%record_columns, self%record_column_names)
            call self%note_given('record_columns')
        else if (any(record_columns(1:2) /= -1)) then
            self%record_columns = max(0, record_columns)
            ! one value alone: the value's column
            if (all(record_columns(2:4) == -1)) self%record_columns = [0, record_columns(1), 0, 0]
            call self%note_given('record_columns')
        end if
        self%record_frame_rate = record_frame_rate
        self%record_axes = record_axes
        self%record_split = record_split
        self%record_point = record_point
        self%record_view = record_view
        self%record_scale = record_scale
        self%record_units = record_units
        self%loss = loss
        if (u_inertia(1) /= PERIOD_UNSET) then
            self%u_inertia(1) = u_inertia(1)
            call self%note_given('u_inertia')
        end if
        if (u_inertia(2) /= PERIOD_UNSET) then
            self%u_inertia(2) = u_inertia(2)
            call self%note_given('u_inertia(2)')
        end if
        self%u_cg_depth = u_cg_depth
        self%u_cg_offset = u_cg_offset
        self%u_r = u_r
        self%u_lambda = u_lambda
        self%tare_i1 = tare_i1
        self%u_tare_i1 = u_tare_i1
        self%tare_mass = tare_mass
        self%added_inertia = added_inertia
        self%u_added_inertia = u_added_inertia
        self%on_failure = on_failure
        self%calibration = calibration
        self%tare = tare
        self%session = session
        self%n_periods = 0
        do while (self%n_periods < MAX_PERIODS)
            if (self%periods(self%n_periods + 1) == PERIOD_UNSET) exit
            self%n_periods = self%n_periods + 1
        end do
    contains
        !> The namelist's variables at the group's values (the defaults, before a read).
        subroutine defaults()
            periods = self%periods
            amplitudes = self%amplitudes
            cycles = self%cycles
            record = self%record
            quantity = ''
            estimate = self%estimate
            u_mass = self%u_mass
            u_l = self%u_l
            u_l_prime = self%u_l_prime
            u_b = self%u_b
            u_b_prime = self%u_b_prime
            u_g = self%u_g
            u_period = self%u_period
            u_amplitude = self%u_amplitude
            u_amplitude_scale = self%u_amplitude_scale
            monte_carlo = self%monte_carlo
            seed = self%seed
            trials = self%trials
            record_columns = -1
            record_units = self%record_units
            loss = self%loss
            u_inertia = PERIOD_UNSET
            u_cg_depth = self%u_cg_depth
            u_cg_offset = self%u_cg_offset
            u_r = self%u_r
            u_lambda = self%u_lambda
            tare_i1 = self%tare_i1
            u_tare_i1 = self%u_tare_i1
            tare_mass = self%tare_mass
            added_inertia = self%added_inertia
            u_added_inertia = self%u_added_inertia
            record_frame_rate = self%record_frame_rate
            record_axes = self%record_axes
            record_split = self%record_split
            record_point = self%record_point
            record_view = self%record_view
            record_scale = self%record_scale
            on_failure = self%on_failure
            session = self%session
            calibration = self%calibration
            tare = self%tare
        end subroutine defaults
        !> The read with record_columns as text: words(1:3), the other variables the host's.
        subroutine read_words(ios2, msg2)
            integer, intent(out) :: ios2
            character(len=*), intent(inout) :: msg2
            character(len=256) :: record_columns(4)
            namelist /measurement/ periods, amplitudes, cycles, record, quantity, estimate, &
                u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude, &
                monte_carlo, seed, trials, record_columns, record_units, loss, u_inertia, &
                u_cg_depth, u_cg_offset, u_r, u_lambda, tare_i1, u_tare_i1, tare_mass, &
                added_inertia, u_added_inertia, on_failure, session, record_frame_rate, &
                calibration, tare, u_amplitude_scale, record_axes, record_split, &
                record_point, record_view, record_scale
            record_columns = ''
            read (rec, nml=measurement, iostat=ios2, iomsg=msg2)
            words = record_columns
        end subroutine read_words
    end subroutine read_measurement

    function echo_measurement(self) result(line)
        class(measurement_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &measurement'
        if (self%n_periods > 0) line = line//' periods = '// &
            rlist_short(self%periods(1:self%n_periods))//', amplitudes = '// &
            rlist_short(self%amplitudes(1:self%n_periods))//','
        if (len_trim(self%record) > 0) line = line//' record = '//quoted(self%record)// &
            ', quantity = '//quoted(self%quantity)//','
        if (self%n_periods > 0) then
            if (any(self%cycles(1:self%n_periods) /= 1.0_dp)) line = line//' cycles = '// &
                rlist_short(self%cycles(1:self%n_periods))//','
        end if
        if (len_trim(self%trials) > 0) line = line//' trials = '//quoted(self%trials)//','
        if (len_trim(self%calibration) > 0) line = line//' calibration = '// &
            quoted(self%calibration)//','
        if (len_trim(self%tare) > 0) line = line//' tare = '//quoted(self%tare)//','
        if (self%gave('record_columns')) then
            line = line//' record_columns = '//column_text(1)//', '//column_text(2)//', '// &
                column_text(3)
            if (trim(self%quantity) == 'rates') line = line//', '//column_text(4)
            line = line//','
        end if
        if (trim(self%quantity) == 'rates') line = line//' record_axes = '// &
            quoted(self%record_axes)//','
        if (self%record_split) line = line//' record_split = .true.,'
        if (trim(self%quantity) == 'point') line = line//' record_point = '// &
            rlist_short(self%record_point)//', record_view = '//quoted(self%record_view)// &
            ', record_scale = '//rshort(self%record_scale)//','
        if (self%record_frame_rate > 0.0_dp) line = line//' record_frame_rate = '// &
            rshort(self%record_frame_rate)//','
        if (len_trim(self%record_units) > 0) line = line//' record_units = '// &
            quoted(self%record_units)//','
        if (trim(self%loss) /= 'squares') line = line//' loss = '//quoted(self%loss)//','
        line = line//' estimate = '//quoted(self%estimate)//', u_mass = '// &
            rshort(self%u_mass)//', u_l = '//rshort(self%u_l)//', u_l_prime = '// &
            rshort(self%u_l_prime)//', u_b = '//rshort(self%u_b)//', u_b_prime = '// &
            rshort(self%u_b_prime)//', u_g = '//rshort(self%u_g)//', u_period = '// &
            rshort(self%u_period)//', u_amplitude = '//rshort(self%u_amplitude)
        if (self%u_amplitude_scale > 0.0_dp) line = line//', u_amplitude_scale = '// &
            rshort(self%u_amplitude_scale)
        if (any(self%u_inertia > 0.0_dp)) line = line//', u_inertia = '// &
            rlist_short(self%u_inertia)
        if (self%u_cg_depth > 0.0_dp .or. self%u_cg_offset > 0.0_dp) line = line// &
            ', u_cg_depth = '//rshort(self%u_cg_depth)//', u_cg_offset = '// &
            rshort(self%u_cg_offset)
        if (self%u_r > 0.0_dp .or. self%u_lambda > 0.0_dp) line = line//', u_r = '// &
            rshort(self%u_r)//', u_lambda = '//rshort(self%u_lambda)
        if (self%tare_i1 > 0.0_dp .or. self%tare_mass > 0.0_dp .or. self%u_tare_i1 > 0.0_dp) &
            line = line//', tare_i1 = '//rshort(self%tare_i1)//', u_tare_i1 = '// &
            rshort(self%u_tare_i1)//', tare_mass = '//rshort(self%tare_mass)
        if (self%added_inertia > 0.0_dp .or. self%u_added_inertia > 0.0_dp) &
            line = line//', added_inertia = '//rshort(self%added_inertia)// &
            ', u_added_inertia = '//rshort(self%u_added_inertia)
        if (lower(adjustl(self%on_failure)) /= 'stop') line = line//', on_failure = '// &
            quoted(self%on_failure)
        if (len_trim(self%session) > 0) line = line//', session = '//quoted(self%session)
        line = line//', monte_carlo = '//itoa(self%monte_carlo)//', seed = '// &
            itoa(self%seed)//' /'
    contains
        !> record_columns(k) as given: its number, or its name quoted.
        function column_text(k) result(c)
            integer, intent(in) :: k
            character(len=:), allocatable :: c
            c = itoa(self%record_columns(k))
            if (self%record_columns(k) == 0 .and. len_trim(self%record_column_names(k)) > 0) &
                c = quoted(self%record_column_names(k))
        end function column_text
    end function echo_measurement

    !> record_columns read as text (words, '' where not given): each a column's number (an
    !! integer) or its name in the header (lower case, trimmed); one word alone is the
    !! value's column.  A word that starts as a number does but is none (1.5, -2, 1e3) is
    !! kept as a name, for the check to refuse.
    pure subroutine column_words(words, columns, names)
        character(len=*), intent(in) :: words(4)
        integer, intent(out) :: columns(4)
        character(len=*), intent(out) :: names(4)
        character(len=len(words)) :: w(4)
        integer :: k, ios
        w = words
        if (len_trim(w(1)) > 0 .and. all(len_trim(w(2:4)) == 0)) w = [character(len=len(w)) :: &
            '', w(1), '', '']
        columns = 0
        names = ''
        do k = 1, 4
            if (len_trim(w(k)) == 0) cycle
            if (verify(trim(adjustl(w(k))), '0123456789') == 0 .and. &
                len_trim(adjustl(w(k))) <= 6) then
                read (w(k), *, iostat=ios) columns(k)
                if (ios == 0) cycle
                columns(k) = 0
            end if
            names(k) = lower(trim(adjustl(w(k))))
        end do
    end subroutine column_words

    !> True when the blank-separated word `word` (e.g. 'c_q') is in estimate.
    pure logical function estimated(self, word)
        class(measurement_group_t), intent(in) :: self
        character(len=*), intent(in) :: word        !! one of ESTIMATES_ALLOWED
        estimated = index(' '//lower(self%estimate)//' ', ' '//lower(trim(word))//' ') > 0
    end function estimated

    !> The standard uncertainties of I2 and I3 the run takes: a value given for u_inertia(1)
    !! alone serves both.
    pure function u_inertia_of(self) result(u)
        class(measurement_group_t), intent(in) :: self
        real(dp) :: u(2)
        u = self%u_inertia
        if (self%gave('u_inertia') .and. .not. self%gave('u_inertia(2)')) u(2) = u(1)
    end function u_inertia_of

    !> quantity, record_units and loss in lower case, the quantity from record_units when
    !! given; the cycles of every period (one value serves all, 1 when not given); one
    !! u_inertia for I2 and I3 (u_inertia_of); record and trials relative to the deck's
    !! folder.
    pure subroutine normalise_measurement(self, deck_path)
        class(measurement_group_t), intent(inout) :: self
        character(len=*), intent(in) :: deck_path   !! the deck as given
        integer :: nc
        self%quantity = lower(adjustl(self%quantity))
        nc = count(self%cycles /= PERIOD_UNSET)
        if (nc == 1) self%cycles(2:max(1, self%n_periods)) = self%cycles(1)
        where (self%cycles == PERIOD_UNSET) self%cycles = 1.0_dp
        self%record_axes = lower(adjustl(self%record_axes))
        self%record_view = lower(adjustl(self%record_view))
        if (len_trim(self%record_units) > 0) then
            self%record_units = lower(adjustl(self%record_units))
            if (trim(self%quantity) /= 'rates' .and. trim(self%quantity) /= 'point') &
                self%quantity = merge('rate ', 'angle', index(self%record_units, '/s') > 0)
        end if
        self%loss = lower(adjustl(self%loss))
        self%on_failure = lower(adjustl(self%on_failure))
        self%u_inertia = self%u_inertia_of()
        self%record_path = ''
        if (len_trim(self%record) > 0) self%record_path = record_in_folder(deck_path, &
                                                                           self%record)
        self%trials_path = ''
        if (len_trim(self%trials) > 0) self%trials_path = record_in_folder(deck_path, &
                                                                           self%trials)
        self%calibration_path = ''
        if (len_trim(self%calibration) > 0) &
            self%calibration_path = record_in_folder(deck_path, self%calibration)
        self%tare_path = ''
        if (len_trim(self%tare) > 0) self%tare_path = record_in_folder(deck_path, self%tare)
    end subroutine normalise_measurement

    ! ------------------------------------------------------------------ &tensor

    function tensor_name() result(s)
        character(len=:), allocatable :: s
        s = 'tensor'
    end function tensor_name

    function tensor_spec() result(s)
        character(len=:), allocatable :: s
        s = 'hangs:c1 u_mass:r1 u_l:r1 u_l_prime:r1 u_b:r1 u_b_prime:r1 u_g:r1 u_period:r1 '// &
            'u_amplitude:r1 u_direction:r1 monte_carlo:i1 seed:i1 cg:r3 plan:i1 '// &
            'plan_add:i1 fixture_mass:r1 fixture_cg:r3 fixture_inertia:r9 u_fixture_mass:r1 '// &
            'u_fixture_cg:r3 u_fixture_inertia:r9 fixture_frame:c1 estimate:c1 u_attitude:r1'
    end function tensor_spec

    !> &tensor hangs, the standard uncertainties of the hangs' inputs, monte_carlo, seed, cg,
    !! plan.
    subroutine read_tensor(self, rec, ios, msg)
        class(tensor_group_t), intent(inout) :: self    !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: hangs
        real(dp) :: u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude
        real(dp) :: u_direction, cg(3)
        integer :: monte_carlo, seed, plan, plan_add
        real(dp) :: fixture_mass, fixture_cg(3), fixture_inertia(3, 3), u_fixture_mass
        real(dp) :: u_fixture_cg(3), u_fixture_inertia(3, 3), u_attitude
        character(len=256) :: fixture_frame, estimate
        namelist /tensor/ hangs, u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, &
            u_amplitude, u_direction, monte_carlo, seed, cg, plan, plan_add, fixture_mass, &
            fixture_cg, fixture_inertia, u_fixture_mass, u_fixture_cg, u_fixture_inertia, &
            fixture_frame, estimate, u_attitude
        plan_add = self%plan_add
        fixture_mass = self%fixture_mass
        fixture_cg = self%fixture_cg
        fixture_inertia = self%fixture_inertia
        u_fixture_mass = self%u_fixture_mass
        u_fixture_cg = NOT_GIVEN
        u_fixture_inertia = NOT_GIVEN
        fixture_frame = self%fixture_frame
        estimate = self%estimate
        u_attitude = self%u_attitude
        hangs = self%hangs
        u_mass = self%u(1)
        u_l = self%u(2)
        u_l_prime = self%u(3)
        u_b = self%u(4)
        u_b_prime = self%u(5)
        u_g = self%u(6)
        u_period = self%u(7)
        u_amplitude = self%u(8)
        u_direction = self%u_direction
        monte_carlo = self%monte_carlo
        seed = self%seed
        plan = self%plan
        cg = NOT_GIVEN
        read (rec, nml=tensor, iostat=ios, iomsg=msg)
        self%hangs = hangs
        self%u = [u_mass, u_l, u_l_prime, u_b, u_b_prime, u_g, u_period, u_amplitude]
        self%u_direction = u_direction
        self%monte_carlo = monte_carlo
        self%seed = seed
        self%plan = plan
        self%cg_given = any(cg /= NOT_GIVEN)
        if (self%cg_given) self%cg = merge(cg, 0.0_dp, cg /= NOT_GIVEN)
        self%plan_add = plan_add
        self%fixture_mass = fixture_mass
        self%fixture_cg = fixture_cg
        self%fixture_inertia = fixture_inertia
        self%u_fixture_mass = u_fixture_mass
        ! one u given for a vector or a matrix is the u of each of its entries
        if (u_fixture_cg(1) /= NOT_GIVEN .and. all(u_fixture_cg(2:3) == NOT_GIVEN)) &
            u_fixture_cg(2:3) = u_fixture_cg(1)
        self%u_fixture_cg = merge(u_fixture_cg, 0.0_dp, u_fixture_cg /= NOT_GIVEN)
        if (u_fixture_inertia(1, 1) /= NOT_GIVEN .and. count(u_fixture_inertia /= NOT_GIVEN) &
            == 1) u_fixture_inertia = u_fixture_inertia(1, 1)
        self%u_fixture_inertia = merge(u_fixture_inertia, 0.0_dp, u_fixture_inertia /= NOT_GIVEN)
        self%fixture_frame = lower(adjustl(fixture_frame))
        self%estimate = lower(adjustl(estimate))
        self%u_attitude = u_attitude
    end subroutine read_tensor

    !> A fixture hung with the body (any of its keys not 0).
    pure logical function tensor_has_fixture(self)
        class(tensor_group_t), intent(in) :: self
        tensor_has_fixture = self%fixture_mass /= 0.0_dp .or. any(self%fixture_cg /= 0.0_dp) &
            .or. any(self%fixture_inertia /= 0.0_dp) .or. self%u_fixture_mass /= 0.0_dp .or. &
            any(self%u_fixture_cg /= 0.0_dp) .or. any(self%u_fixture_inertia /= 0.0_dp)
    end function tensor_has_fixture

    !> estimate = 'tensor cg': the mass centre is fitted with the tensor.
    pure logical function tensor_estimates_cg(self)
        class(tensor_group_t), intent(in) :: self
        tensor_estimates_cg = index(' '//trim(self%estimate)//' ', ' cg ') > 0
    end function tensor_estimates_cg

    function echo_tensor(self) result(line)
        class(tensor_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &tensor hangs = '//quoted(self%hangs)//', u_mass = '// &
            rshort(self%u(1))//', u_l = '//rshort(self%u(2))//', u_l_prime = '// &
            rshort(self%u(3))//', u_b = '//rshort(self%u(4))//', u_b_prime = '// &
            rshort(self%u(5))//', u_g = '//rshort(self%u(6))//', u_period = '// &
            rshort(self%u(7))//', u_amplitude = '//rshort(self%u(8))// &
            ', u_direction = '//rshort(self%u_direction)//', monte_carlo = '// &
            itoa(self%monte_carlo)//', seed = '//itoa(self%seed)
        if (self%cg_given) line = line//', cg = '//rlist_short(self%cg)
        if (self%plan > 0) line = line//', plan = '//itoa(self%plan)
        if (self%plan_add > 0) line = line//', plan_add = '//itoa(self%plan_add)
        if (self%has_fixture()) line = line//', fixture_mass = '//rshort(self%fixture_mass)// &
            ', fixture_cg = '//rlist_short(self%fixture_cg)//', fixture_inertia = '// &
            rlist_short(reshape(self%fixture_inertia, [9]))//', u_fixture_mass = '// &
            rshort(self%u_fixture_mass)//', u_fixture_cg = '//rlist_short(self%u_fixture_cg)// &
            ', u_fixture_inertia = '//rlist_short(reshape(self%u_fixture_inertia, [9]))// &
            ', fixture_frame = '//quoted(trim(self%fixture_frame))
        if (trim(self%estimate) /= 'tensor') line = line//', estimate = '// &
            quoted(trim(self%estimate))//', u_attitude = '//rshort(self%u_attitude)
        line = line//' /'
    end function echo_tensor

    !> The table of hangs relative to the deck's folder.
    pure subroutine normalise_tensor(self, deck_path)
        class(tensor_group_t), intent(inout) :: self
        character(len=*), intent(in) :: deck_path   !! the deck as given
        self%hangs_path = ''
        if (len_trim(self%hangs) > 0) self%hangs_path = record_in_folder(deck_path, self%hangs)
    end subroutine normalise_tensor

    !> &measurement record_axes: the instrument's axes in the body's principal axes b_1,
    !! b_2, b_3 (called x, y, z): 'aligned' (the instrument's x, y, z along b_1, b_2, b_3),
    !! or three signed letters, the body axis along the instrument's x, y and z in turn:
    !! 'z -y x' (its x along b_3, its y along -b_2, its z along b_1); each body axis once.
    !! axes(k, :): the instrument's axis k in b_i; ok .false. for any other text.
    pure subroutine parse_axes(text, axes, ok)
        character(len=*), intent(in) :: text
        real(dp), intent(out) :: axes(3, 3)
        logical, intent(out) :: ok
        character(len=len(text)) :: rest
        character(len=8) :: w
        integer :: k, j, i, sgn
        axes = 0.0_dp
        do k = 1, 3
            axes(k, k) = 1.0_dp
        end do
        ok = .true.
        rest = adjustl(text)
        if (len_trim(rest) == 0 .or. trim(rest) == 'aligned') return
        ok = .false.
        axes = 0.0_dp
        do k = 1, 3
            rest = adjustl(rest)
            i = index(rest, ' ')
            if (i <= 1) return
            w = rest(1:i - 1)
            rest = rest(i:)
            sgn = 1
            if (w(1:1) == '-' .or. w(1:1) == '+') then
                if (w(1:1) == '-') sgn = -1
                w = w(2:)
            end if
            j = index('xyz', trim(w))
            if (len_trim(w) /= 1 .or. j == 0) return
            if (any(axes(:, j) /= 0.0_dp)) return
            axes(k, j) = real(sgn, dp)
        end do
        ok = len_trim(rest) == 0
    end subroutine parse_axes

end module measure_groups
