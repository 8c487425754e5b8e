!> The deck's groups of the scene and of single analyses: &scene (the title, the analyses
!! asked for, the model), &output (simulate's columns), &floquet, &chart (stability) and
!! &design (design).  Each is a type extending deck_group_t with its keys and their
!! defaults, its name and spec, its read from the group's text, its echo, its check
!! (submodule analysis_checks: intent(in)) and, where the run takes a value other than the
!! one given, its normalisation (normalise: words in lower case, the columns in
!! OUTPUT_COLUMNS' order, the design's amplitude of measurement).
module analysis_groups
    use kinds, only: dp
    use status, only: status_t
    use text, only: itoa, rshort, lower, next_word, quoted
    use deck_base, only: deck_group_t, NOT_GIVEN
    use rig_groups, only: suspension_group_t, body_group_t
    implicit none
    private

    !> The columns of a simulation's .dat file, in their order (&output columns picks some).
    character(len=*), parameter, public :: OUTPUT_COLUMNS = 'tau theta1 theta2 theta3 '// &
        'theta4 theta5 theta1_dot theta2_dot theta3_dot theta4_dot theta5_dot Q Q_axis T_BC '// &
        'T_AD energy_error constraint_residual'
    !> Words allowed in &scene analyses.
    character(len=*), parameter, public :: ANALYSES_ALLOWED = &
        'simulate floquet chart work_precision design identify calibrate tensor'
    !> Words allowed in &scene model.
    character(len=*), parameter :: MODELS_ALLOWED = 'kane elastic'
    !> Words allowed in &chart x and y: of a bifilar, and of a platform.
    character(len=*), parameter :: CHART_VARIABLES = 'l b amplitude r lambda inertia_ratio'
    character(len=*), parameter :: PLATFORM_CHART_VARIABLES = 'l radius amplitude '// &
        'cg_offset cg_depth inertia_ratio'
    !> Smallest torsion amplitude of a Floquet analysis (degrees; &floquet, a chart's
    !! amplitude axis, the design's smallest amplitude): the linear limit is reached long
    !! before, and below about 1e-170 degrees products in the variational analysis underflow.
    real(dp), parameter :: FLOQUET_AMPLITUDE_MIN = 1.0e-6_dp
    real(dp), parameter :: FLOQUET_RTOL_MAX = 1.0e-2_dp !! largest &floquet rtol (excluded)
    integer, parameter :: MAX_SEGMENTS = 64             !! most &floquet shooting segments
    integer, parameter :: MAX_CHART_N = 1000            !! most chart points along one axis
    integer, parameter :: MAX_CHART_POINTS = 250000     !! most chart points, nx*ny
    integer, parameter :: MAX_DESIGN_AMPLITUDES = 100   !! most &design n_amplitudes

    !> &scene.
    type, extends(deck_group_t), public :: scene_group_t
        character(len=256) :: title = ''
        character(len=256) :: analyses = 'simulate'    !! words of ANALYSES_ALLOWED
        character(len=256) :: model = 'kane'            !! MODELS_ALLOWED: 'kane' or 'elastic'
    contains
        procedure, nopass :: name => scene_name
        procedure, nopass :: spec => scene_spec
        procedure :: read_text => read_scene
        procedure :: echo => echo_scene
        procedure :: check => check_scene
        procedure :: normalise => normalise_scene
        procedure :: requested
    end type scene_group_t

    !> &output: the .dat columns, blank-separated names of OUTPUT_COLUMNS, or of a platform's
    !! (platform_columns; not given: all of them) (normalise: in their order).
    type, extends(deck_group_t), public :: output_group_t
        character(len=512) :: columns = OUTPUT_COLUMNS
    contains
        procedure, nopass :: name => output_name
        procedure, nopass :: spec => output_spec
        procedure :: read_text => read_output
        procedure :: echo => echo_output
        procedure :: check => check_output
        procedure :: normalise => normalise_output
    end type output_group_t

    !> &floquet.
    type, extends(deck_group_t), public :: floquet_group_t
        real(dp) :: amplitude = 45.0_dp           !! degrees of theta4, 0 < a < 180
        integer  :: segments = 1                  !! shooting segments, 1..64
        real(dp) :: rtol = 1.0e-10_dp             !! 1e-14 <= rtol < 1e-2
    contains
        procedure, nopass :: name => floquet_name
        procedure, nopass :: spec => floquet_spec
        procedure :: read_text => read_floquet
        procedure :: echo => echo_floquet
        procedure :: check => check_floquet
    end type floquet_group_t

    !> &chart (axis variables: see CHART_VARIABLES, PLATFORM_CHART_VARIABLES).
    type, extends(deck_group_t), public :: chart_group_t
        character(len=256) :: x = 'l', y = 'amplitude'
        real(dp) :: x_min = 0.5_dp, x_max = 4.0_dp
        real(dp) :: y_min = 5.0_dp, y_max = 90.0_dp
        integer  :: nx = 40, ny = 40
    contains
        procedure, nopass :: name => chart_name
        procedure, nopass :: spec => chart_spec
        procedure :: read_text => read_chart
        procedure :: echo => echo_chart
        procedure :: check => check_chart
        procedure :: normalise => normalise_chart
    end type chart_group_t

    !> &design (analysis design): candidate rigs l = l' (and b) and the instruments'
    !! standard uncertainties, all in deck units (period in s); checked only when the
    !! analysis is requested.
    type, extends(deck_group_t), public :: design_group_t
        real(dp) :: l_min = 0.4_dp, l_max = 3.0_dp
        integer  :: nl = 60
        real(dp) :: b_min = 0.0_dp, b_max = 0.0_dp   !! 0, 0 with nb = 1: the deck's b
        integer  :: nb = 1
        !> the body's spacing b' (0, 0 with nb_prime = 1: the deck's b')
        real(dp) :: b_prime_min = 0.0_dp, b_prime_max = 0.0_dp
        integer  :: nb_prime = 1
        !> a platform's radius (0, 0 with nradius = 1: the deck's): the support's circle,
        !! the body's in the deck's ratio radius_prime/radius
        real(dp) :: radius_min = 0.0_dp, radius_max = 0.0_dp
        integer  :: nradius = 1
        real(dp) :: amplitude_max = 50.0_dp       !! degrees, 0 < a <= 90
        !> the amplitude (degrees) at which the precision is predicted; NOT_GIVEN: not
        !! given, then min(25, amplitude_max) (measure_amplitude, normalise)
        real(dp) :: amplitude_measure = NOT_GIVEN
        integer  :: n_amplitudes = 6
        real(dp) :: u_mass = 1.0e-3_dp, u_l = 1.0e-3_dp
        real(dp) :: u_b = 5.0e-4_dp, u_period = 1.0e-4_dp
    contains
        procedure, nopass :: name => design_name
        procedure, nopass :: spec => design_spec
        procedure :: read_text => read_design
        procedure :: echo => echo_design
        procedure :: check => check_design
        procedure :: normalise => normalise_design
        procedure :: measure_amplitude
    end type design_group_t

    public :: platform_columns

    ! ---- submodule analysis_checks
    interface
        !> &scene: model and analyses known words.
        module subroutine check_scene(self, stat)
            class(scene_group_t), intent(in) :: self
            type(status_t), intent(inout) :: stat
        end subroutine check_scene
        !> &output: the .dat columns (those of a platform of sus%cables >= 3).
        module subroutine check_output(self, sus, stat)
            class(output_group_t), intent(in) :: self
            type(suspension_group_t), intent(in) :: sus
            type(status_t), intent(inout) :: stat
        end subroutine check_output
        !> &floquet: amplitude, segments, rtol.
        module subroutine check_floquet(self, stat)
            class(floquet_group_t), intent(in) :: self
            type(status_t), intent(inout) :: stat
        end subroutine check_floquet
        !> &chart: the two axes (a platform's variables when sus%cables >= 3).
        module subroutine check_chart(self, sus, stat)
            class(chart_group_t), intent(in) :: self
            type(suspension_group_t), intent(in) :: sus
            type(status_t), intent(inout) :: stat
        end subroutine check_chart
        !> &design: the candidate grid and uncertainties, against the deck's rig.
        module subroutine check_design(self, sus, bod, stat)
            class(design_group_t), intent(in) :: self
            type(suspension_group_t), intent(in) :: sus     !! the suspension, normalised
            type(body_group_t), intent(in) :: bod
            type(status_t), intent(inout) :: stat
        end subroutine check_design
    end interface

contains

    ! ------------------------------------------------------------------ &scene

    function scene_name() result(s)
        character(len=:), allocatable :: s
        s = 'scene'
    end function scene_name

    function scene_spec() result(s)
        character(len=:), allocatable :: s
        s = 'title:c1 analyses:c1 model:c1'
    end function scene_spec

    !> &scene title, analyses, model.
    subroutine read_scene(self, rec, ios, msg)
        class(scene_group_t), intent(inout) :: self !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: title, analyses, model
        namelist /scene/ title, analyses, model
        title = self%title
        analyses = self%analyses
        model = self%model
        read (rec, nml=scene, iostat=ios, iomsg=msg)
        self%title = title
        self%analyses = analyses
        self%model = model
    end subroutine read_scene

    function echo_scene(self) result(line)
        class(scene_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &scene title = '//quoted(self%title)//', analyses = '// &
            quoted(self%analyses)//', model = '//quoted(self%model)//' /'
    end function echo_scene

    !> analyses and model in lower case, tabs in analyses taken as blanks.
    pure subroutine normalise_scene(self)
        class(scene_group_t), intent(inout) :: self
        integer :: k
        do k = 1, len(self%analyses)
            if (self%analyses(k:k) == achar(9)) self%analyses(k:k) = ' '
        end do
        self%analyses = lower(adjustl(self%analyses))
        self%model = lower(adjustl(self%model))
    end subroutine normalise_scene

    !> True when `word` is one of the blank-separated words of analyses.
    pure logical function requested(self, word)
        class(scene_group_t), intent(in) :: self
        character(len=*), intent(in) :: word        !! analysis name, e.g. 'simulate'
        integer :: i1, i2
        character(len=len(self%analyses)) :: list
        requested = .false.
        list = lower(self%analyses)
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            if (list(i1:i2) == lower(trim(adjustl(word)))) then
                requested = .true.
                return
            end if
        end do
    end function requested

    ! ------------------------------------------------------------------ &output

    function output_name() result(s)
        character(len=:), allocatable :: s
        s = 'output'
    end function output_name

    function output_spec() result(s)
        character(len=:), allocatable :: s
        s = 'columns:c1'
    end function output_spec

    !> &output columns.
    subroutine read_output(self, rec, ios, msg)
        class(output_group_t), intent(inout) :: self    !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=512) :: columns
        namelist /output/ columns
        columns = self%columns
        read (rec, nml=output, iostat=ios, iomsg=msg)
        self%columns = columns
    end subroutine read_output

    function echo_output(self) result(line)
        class(output_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &output columns = '//quoted(self%columns)//' /'
    end function echo_output

    !> The columns of the .dat file of a platform of n cables (&suspension cables >= 3), in
    !! their order: time t, the pose of the body's frame (x, y, z of its origin; yaw, pitch,
    !! roll: R = Rz(yaw) Ry(pitch) Rx(roll)), their rates, each cable's tension T1 .. Tn,
    !! the energy error and the constraint residual.
    pure function platform_columns(n) result(s)
        integer, intent(in) :: n                !! cables
        character(len=:), allocatable :: s
        integer :: k
        s = 't x y z yaw pitch roll x_dot y_dot z_dot yaw_dot pitch_dot roll_dot'
        do k = 1, n
            s = s//' T'//itoa(k)
        end do
        s = s//' energy_error constraint_residual'
    end function platform_columns

    !> The columns asked for (names of OUTPUT_COLUMNS, or of a platform of `cables` >= 3
    !! cables' columns, in any case, tabs as blanks; checked) in that list's order, with its
    !! spelling.  A platform's deck that leaves &output columns as they are (OUTPUT_COLUMNS)
    !! has every platform column.
    pure subroutine normalise_output(self, cables)
        class(output_group_t), intent(inout) :: self
        integer, intent(in) :: cables           !! &suspension cables
        character(len=len(self%columns)) :: list
        character(len=:), allocatable :: known, cols
        integer :: i1, i2, j1, j2
        if (cables > 2) then
            cols = platform_columns(cables)
            if (trim(self%columns) == OUTPUT_COLUMNS) then
                self%columns = cols
                return
            end if
        else
            cols = OUTPUT_COLUMNS
        end if
        list = self%columns
        do i1 = 1, len(list)
            if (list(i1:i1) == achar(9)) list(i1:i1) = ' '
        end do
        list = lower(list)
        known = lower(cols)
        self%columns = ''
        j2 = 0
        do
            call next_word(known, j2, j1)
            if (j1 == 0) exit
            i2 = 0
            do
                call next_word(list, i2, i1)
                if (i1 == 0) exit
                if (list(i1:i2) == known(j1:j2)) then
                    self%columns = trim(self%columns)//' '//cols(j1:j2)
                    exit
                end if
            end do
        end do
        self%columns = adjustl(self%columns)
    end subroutine normalise_output

    ! ------------------------------------------------------------------ &floquet

    function floquet_name() result(s)
        character(len=:), allocatable :: s
        s = 'floquet'
    end function floquet_name

    function floquet_spec() result(s)
        character(len=:), allocatable :: s
        s = 'amplitude:r1 segments:i1 rtol:r1'
    end function floquet_spec

    !> &floquet amplitude, segments, rtol.
    subroutine read_floquet(self, rec, ios, msg)
        class(floquet_group_t), intent(inout) :: self   !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: amplitude, rtol
        integer :: segments
        namelist /floquet/ amplitude, segments, rtol
        amplitude = self%amplitude
        segments = self%segments
        rtol = self%rtol
        read (rec, nml=floquet, iostat=ios, iomsg=msg)
        self%amplitude = amplitude
        self%segments = segments
        self%rtol = rtol
    end subroutine read_floquet

    function echo_floquet(self) result(line)
        class(floquet_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &floquet amplitude = '//rshort(self%amplitude)//', segments = '// &
            itoa(self%segments)//', rtol = '//rshort(self%rtol)//' /'
    end function echo_floquet

    ! ------------------------------------------------------------------ &chart

    function chart_name() result(s)
        character(len=:), allocatable :: s
        s = 'chart'
    end function chart_name

    function chart_spec() result(s)
        character(len=:), allocatable :: s
        s = 'x:c1 x_min:r1 x_max:r1 nx:i1 y:c1 y_min:r1 y_max:r1 ny:i1'
    end function chart_spec

    !> &chart x, x_min, x_max, nx, y, y_min, y_max, ny.
    subroutine read_chart(self, rec, ios, msg)
        class(chart_group_t), intent(inout) :: self !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: x, y
        real(dp) :: x_min, x_max, y_min, y_max
        integer :: nx, ny
        namelist /chart/ x, x_min, x_max, nx, y, y_min, y_max, ny
        x = self%x
        x_min = self%x_min
        x_max = self%x_max
        nx = self%nx
        y = self%y
        y_min = self%y_min
        y_max = self%y_max
        ny = self%ny
        read (rec, nml=chart, iostat=ios, iomsg=msg)
        self%x = x
        self%x_min = x_min
        self%x_max = x_max
        self%nx = nx
        self%y = y
        self%y_min = y_min
        self%y_max = y_max
        self%ny = ny
    end subroutine read_chart

    function echo_chart(self) result(line)
        class(chart_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &chart x = '//quoted(self%x)//', x_min = '//rshort(self%x_min)// &
            ', x_max = '//rshort(self%x_max)//', nx = '//itoa(self%nx)//', y = '// &
            quoted(self%y)//', y_min = '//rshort(self%y_min)//', y_max = '// &
            rshort(self%y_max)//', ny = '//itoa(self%ny)//' /'
    end function echo_chart

    !> The axes' variables in lower case.
    pure subroutine normalise_chart(self)
        class(chart_group_t), intent(inout) :: self
        self%x = lower(adjustl(self%x))
        self%y = lower(adjustl(self%y))
    end subroutine normalise_chart

    ! ------------------------------------------------------------------ &design

    function design_name() result(s)
        character(len=:), allocatable :: s
        s = 'design'
    end function design_name

    function design_spec() result(s)
        character(len=:), allocatable :: s
        s = 'l_min:r1 l_max:r1 nl:i1 b_min:r1 b_max:r1 nb:i1 amplitude_max:r1 '// &
            'n_amplitudes:i1 u_mass:r1 u_l:r1 u_b:r1 u_period:r1 b_prime_min:r1 '// &
            'b_prime_max:r1 nb_prime:i1 amplitude_measure:r1 radius_min:r1 radius_max:r1 '// &
            'nradius:i1'
    end function design_spec

    !> &design l_min, l_max, nl, b_min, b_max, nb, b_prime_min, b_prime_max, nb_prime,
    !! radius_min, radius_max, nradius, amplitude_max, n_amplitudes, amplitude_measure,
    !! u_mass, u_l, u_b, u_period.
    subroutine read_design(self, rec, ios, msg)
        class(design_group_t), intent(inout) :: self    !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: l_min, l_max, b_min, b_max, amplitude_max, u_mass, u_l, u_b, u_period
        real(dp) :: b_prime_min, b_prime_max, amplitude_measure, radius_min, radius_max
        integer :: nl, nb, n_amplitudes, nb_prime, nradius
        namelist /design/ l_min, l_max, nl, b_min, b_max, nb, amplitude_max, n_amplitudes, &
            u_mass, u_l, u_b, u_period, b_prime_min, b_prime_max, nb_prime, amplitude_measure, &
            radius_min, radius_max, nradius
        l_min = self%l_min
        l_max = self%l_max
        nl = self%nl
        b_min = self%b_min
        b_max = self%b_max
        nb = self%nb
        b_prime_min = self%b_prime_min
        b_prime_max = self%b_prime_max
        nb_prime = self%nb_prime
        radius_min = self%radius_min
        radius_max = self%radius_max
        nradius = self%nradius
        amplitude_measure = self%amplitude_measure
        amplitude_max = self%amplitude_max
        n_amplitudes = self%n_amplitudes
        u_mass = self%u_mass
        u_l = self%u_l
        u_b = self%u_b
        u_period = self%u_period
        read (rec, nml=design, iostat=ios, iomsg=msg)
        self%l_min = l_min
        self%l_max = l_max
        self%nl = nl
        self%b_min = b_min
        self%b_max = b_max
        self%nb = nb
        self%b_prime_min = b_prime_min
        self%b_prime_max = b_prime_max
        self%nb_prime = nb_prime
        self%radius_min = radius_min
        self%radius_max = radius_max
        self%nradius = nradius
        self%amplitude_measure = amplitude_measure
        self%amplitude_max = amplitude_max
        self%n_amplitudes = n_amplitudes
        self%u_mass = u_mass
        self%u_l = u_l
        self%u_b = u_b
        self%u_period = u_period
    end subroutine read_design

    function echo_design(self) result(line)
        class(design_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &design l_min = '//rshort(self%l_min)//', l_max = '//rshort(self%l_max)// &
            ', nl = '//itoa(self%nl)//', b_min = '//rshort(self%b_min)//', b_max = '// &
            rshort(self%b_max)//', nb = '//itoa(self%nb)//', b_prime_min = '// &
            rshort(self%b_prime_min)//', b_prime_max = '//rshort(self%b_prime_max)// &
            ', nb_prime = '//itoa(self%nb_prime)
        if (self%nradius /= 1 .or. self%radius_min /= 0.0_dp) line = line// &
            ', radius_min = '//rshort(self%radius_min)//', radius_max = '// &
            rshort(self%radius_max)//', nradius = '//itoa(self%nradius)
        line = line//', amplitude_max = '// &
            rshort(self%amplitude_max)//', n_amplitudes = '//itoa(self%n_amplitudes)// &
            ', amplitude_measure = '//rshort(self%amplitude_measure)//', u_mass = '// &
            rshort(self%u_mass)//', u_l = '//rshort(self%u_l)//', u_b = '// &
            rshort(self%u_b)//', u_period = '//rshort(self%u_period)//' /'
    end function echo_design

    !> The amplitude (degrees) at which the precision is predicted: amplitude_measure, or
    !! min(25, amplitude_max) when not given.
    pure real(dp) function measure_amplitude(self) result(a)
        class(design_group_t), intent(in) :: self
        a = self%amplitude_measure
        if (a == NOT_GIVEN) a = min(25.0_dp, self%amplitude_max)
    end function measure_amplitude

    !> amplitude_measure as the analysis takes it (measure_amplitude).
    pure subroutine normalise_design(self)
        class(design_group_t), intent(inout) :: self
        self%amplitude_measure = self%measure_amplitude()
    end subroutine normalise_design

end module analysis_groups
