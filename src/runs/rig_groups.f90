!> The deck's groups of the rig: &suspension, &body, &damping, &cables (the rig_t of module
!! rig), &start (its start_t) and &integration (its accuracy_t and output times).  Each is a
!! type extending deck_group_t with its keys and their defaults, its name and spec, its read
!! from the group's text, its echo, its check (submodule rig_checks: intent(in), a check
!! never changes a value) and, where the run takes a value other than the one given, its
!! normalisation (normalise: a platform's equivalent pair b = 2 radius, the mass centre
!! from cg_depth and cg_offset, words in lower case, angles reduced modulo 2 pi).
!!
!! A platform (&suspension cables >= 3) is given either as a regular polygon (radius,
!! radius_prime, l) or point by point (support_points(3, n) in the support's frame,
!! body_points(3, n) in the body's, lengths(n)); its body's mass centre by cg_offset(2)
!! (x, y in the body's frame) and cg_depth; its inertia as the bifilar's (inertia(3),
!! btilde) in the axes (vertical, x, y) of the body's frame.  Module platform_rig makes
!! the model's platform_t of these groups.
!!
!! The defaults are the paper's dimensionless scene (a uniform rod, b = b' = 1, l = l' = 2,
!! g = 1); rig_t, start_t and accuracy_t (module rig) start from the same constants.
module rig_groups
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t
    use text, only: itoa, rshort, rlist_short, lower, quoted
    use deck_base, only: deck_group_t, NOT_GIVEN
    implicit none
    private

    ! ---- the defaults (written once: the groups' keys and module rig's types use them)
    real(dp), parameter, public :: DEFAULT_B = 1.0_dp, DEFAULT_B_PRIME = 1.0_dp
    real(dp), parameter, public :: DEFAULT_L = 2.0_dp, DEFAULT_L_PRIME = 2.0_dp
    real(dp), parameter, public :: DEFAULT_G = 1.0_dp
    real(dp), parameter, public :: DEFAULT_MASS = 1.0_dp
    real(dp), parameter, public :: DEFAULT_INERTIA(3) = [0.125_dp, 0.1458333333333333_dp, &
                                                         0.1458333333333333_dp]
    real(dp), parameter, public :: DEFAULT_R = 0.7071067811865476_dp
    real(dp), parameter, public :: DEFAULT_LAMBDA = 0.7853981633974483_dp
    !> the identity; btilde(i,:) is row i as printed in the paper
    real(dp), parameter, public :: DEFAULT_BTILDE(3, 3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, &
        0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
    real(dp), parameter, public :: DEFAULT_SWAY_DEPTH = 1.0_dp
    real(dp), parameter, public :: DEFAULT_C_V = 0.0_dp, DEFAULT_C_Q = 0.0_dp
    real(dp), parameter, public :: DEFAULT_STIFFNESS = 1.0e6_dp
    real(dp), parameter, public :: DEFAULT_CABLE_DAMPING = 0.05_dp
    character(len=*), parameter, public :: DEFAULT_MODE = 'raised'
    real(dp), parameter, public :: DEFAULT_AMPLITUDE = 45.0_dp, DEFAULT_TILT = 0.0_dp
    real(dp), parameter, public :: DEFAULT_THETA(4) = 0.0_dp, DEFAULT_THETA_DOT(4) = 0.0_dp
    real(dp), parameter, public :: DEFAULT_RTOL = 1.0e-10_dp, DEFAULT_ATOL = 1.0e-12_dp
    logical, parameter, public :: DEFAULT_SENS_ERROR_CONTROL = .false.

    real(dp), parameter, public :: TAU_END_MAX = 1.0e6_dp   !! longest simulation (units of tau)
    !> Most cables of a platform (&suspension cables; platform_geometry's PLATFORM_NMAX).
    integer, parameter, public :: MAX_CABLES = 12
    !> Words allowed in &integration method: 'auto' (radau for model = 'elastic', lsoda for
    !! the paper's model), 'lsoda', 'radau'.
    character(len=*), parameter :: METHODS_ALLOWED = 'auto lsoda radau'
    !> Words allowed in &integration sensitivities: 'forward' (sensitivities integrated with
    !! the state), 'differences' (differences of whole runs, and Floquet's monodromy
    !! integrated as one system with the orbit).
    character(len=*), parameter :: SENSITIVITIES_ALLOWED = 'forward differences'

    !> &suspension (lengths in any one unit; b and b_prime the full distances between the two
    !! cables on the support and on the body).  Tracked (gave): b, b_prime, l, l_prime, g,
    !! cables, radius, radius_prime, support_points, body_points, lengths.
    type, extends(deck_group_t), public :: suspension_group_t
        real(dp) :: b = DEFAULT_B, b_prime = DEFAULT_B_PRIME
        real(dp) :: l = DEFAULT_L, l_prime = DEFAULT_L_PRIME, g = DEFAULT_G
        !> cables >= 3: a platform of that many cables, a regular polygon at radius on the
        !! support and radius_prime on the body, every cable of length l (its torsion is that
        !! of b = 2 radius, b_prime = 2 radius_prime: normalise)
        integer :: cables = 2
        real(dp) :: radius = 0.0_dp, radius_prime = 0.0_dp
        !> or any platform point by point: support_points(:, i) the support point of cable i
        !! in the support's frame (z up), body_points(:, i) its body point in the body's frame
        !! (z up when the body hangs level), lengths(i) its length; NOT_GIVEN where not given
        real(dp) :: support_points(3, MAX_CABLES) = NOT_GIVEN
        real(dp) :: body_points(3, MAX_CABLES) = NOT_GIVEN
        real(dp) :: lengths(MAX_CABLES) = NOT_GIVEN
    contains
        procedure, nopass :: name => suspension_name
        procedure, nopass :: spec => suspension_spec
        procedure :: read_text => read_suspension
        procedure :: echo => echo_suspension
        procedure :: check => check_suspension
        procedure :: normalise => normalise_suspension
        procedure :: pointwise
    end type suspension_group_t

    !> &body.  Tracked (gave): mass, inertia, r, lambda, cg_depth, cg_offset.
    type, extends(deck_group_t), public :: body_group_t
        real(dp) :: mass = DEFAULT_MASS
        real(dp) :: inertia(3) = DEFAULT_INERTIA
        !> the mass centre from C (eq. (21)): r and lambda, or as measured: its depth below the
        !! line CD (cg_depth) and its offset along CD from the midpoint of CD, toward D
        !! (cg_offset); r cos(lambda) = b_prime/2 + cg_offset, r sin(lambda) = cg_depth
        !! (normalise).  On a platform: cg_offset = (cg_offset, cg_offset_y), the mass
        !! centre's x and y in the body's frame (the deck's cg_offset(1:2)), and cg_depth its
        !! depth below the plane of the attachments (their mean height, point by point)
        real(dp) :: r = DEFAULT_R, lambda = DEFAULT_LAMBDA
        real(dp) :: cg_depth = 0.0_dp, cg_offset = 0.0_dp, cg_offset_y = 0.0_dp
        real(dp) :: btilde(3, 3) = DEFAULT_BTILDE
        real(dp) :: sway_depth = DEFAULT_SWAY_DEPTH
        !> the diameter of a sphere that holds the body (0: not given); no moment of inertia
        !! about the mass centre exceeds mass size^2/4 (analysis tensor checks it)
        real(dp) :: size = 0.0_dp
    contains
        procedure, nopass :: name => body_name
        procedure, nopass :: spec => body_spec
        procedure :: read_text => read_body
        procedure :: echo => echo_body
        procedure :: check => check_body
        procedure :: normalise => normalise_body
        procedure :: centre_measured
        procedure :: centre
    end type body_group_t

    !> &start: mode 'raised' (the paper's recipe, amplitude in degrees, tilt and sway in
    !! rad) or 'angles' (theta_1..4 in rad and their rates per unit tau).
    type, extends(deck_group_t), public :: start_group_t
        character(len=256) :: mode = DEFAULT_MODE
        real(dp) :: amplitude = DEFAULT_AMPLITUDE, tilt = DEFAULT_TILT     !! degrees, radians
        !> rad: the cables swung out of their plane at the release (start_t's sway; the body
        !! displaced by about l sway); 0: none
        real(dp) :: sway = 0.0_dp
        real(dp) :: theta(4) = DEFAULT_THETA, theta_dot(4) = DEFAULT_THETA_DOT
    contains
        procedure, nopass :: name => start_name
        procedure, nopass :: spec => start_spec
        procedure :: read_text => read_start
        procedure :: echo => echo_start
        procedure :: check => check_start
        procedure :: normalise => normalise_start
    end type start_group_t

    !> &integration.
    type, extends(deck_group_t), public :: integration_group_t
        real(dp) :: tau_end = 60.0_dp, dtau_out = 0.05_dp
        real(dp) :: rtol = DEFAULT_RTOL, atol = DEFAULT_ATOL
        logical  :: error_estimate = .false.
        character(len=256) :: method = 'auto'      !! METHODS_ALLOWED: the integrator
        !> SENSITIVITIES_ALLOWED: derivatives of whole runs by forward sensitivities or by
        !! the paths of before (differences of runs; Floquet's augmented system)
        character(len=256) :: sensitivities = 'forward'
        !> .true.: forward sensitivities take part in the integrator's error test (a record
        !! fit's Jacobian and budget; Floquet's monodromy always does)
        logical :: sensitivity_error_control = DEFAULT_SENS_ERROR_CONTROL
    contains
        procedure, nopass :: name => integration_name
        procedure, nopass :: spec => integration_spec
        procedure :: read_text => read_integration
        procedure :: echo => echo_integration
        procedure :: check => check_integration
        procedure :: normalise => normalise_integration
    end type integration_group_t

    !> &cables (model = 'elastic' only; read and checked whatever the model).
    type, extends(deck_group_t), public :: cables_group_t
        real(dp) :: stiffness = DEFAULT_STIFFNESS     !! EA/(m g) of each cable, 1 <= k <= 1e12
        real(dp) :: damping = DEFAULT_CABLE_DAMPING   !! damping ratio zeta of each cable, 0..10
    contains
        procedure, nopass :: name => cables_name
        procedure, nopass :: spec => cables_spec
        procedure :: read_text => read_cables
        procedure :: echo => echo_cables
        procedure :: check => check_cables
    end type cables_group_t

    !> &damping: a torque on the body about the vertical, M = -(c_v W + c_q |W| W) n3,
    !! W = omega . n3 (used by the paper's model: simulate, identify).
    type, extends(deck_group_t), public :: damping_group_t
        real(dp) :: c_v = DEFAULT_C_V       !! torque per angular rate (deck units, >= 0)
        real(dp) :: c_q = DEFAULT_C_Q       !! torque per rate squared (deck units, >= 0)
    contains
        procedure, nopass :: name => damping_name
        procedure, nopass :: spec => damping_spec
        procedure :: read_text => read_damping
        procedure :: echo => echo_damping
        procedure :: check => check_damping
    end type damping_group_t

    ! ---- submodule rig_checks: the values of each group in range
    interface
        !> &suspension: lengths and g finite, > 0, in range (a platform's as its equivalent
        !! pair); cables 2 .. MAX_CABLES, radius and radius_prime only with a platform.
        module subroutine check_suspension(self, stat)
            class(suspension_group_t), intent(in) :: self
            type(status_t), intent(inout) :: stat
        end subroutine check_suspension
        !> &body: mass, principal moments (also over m b'^2), the mass centre, btilde.
        module subroutine check_body(self, sus, stat)
            class(body_group_t), intent(in) :: self
            type(suspension_group_t), intent(in) :: sus     !! the suspension, normalised
            type(status_t), intent(inout) :: stat
        end subroutine check_body
        !> &start: mode, amplitude, angles and rates.
        module subroutine check_start(self, stat)
            class(start_group_t), intent(in) :: self
            type(status_t), intent(inout) :: stat
        end subroutine check_start
        !> &integration: method, span, output step, tolerances.
        module subroutine check_integration(self, stat)
            class(integration_group_t), intent(in) :: self
            type(status_t), intent(inout) :: stat
        end subroutine check_integration
        !> &cables: stiffness and damping ratio.
        module subroutine check_cables(self, stat)
            class(cables_group_t), intent(in) :: self
            type(status_t), intent(inout) :: stat
        end subroutine check_cables
        !> &damping: c_v, c_q (in the model's scaled units of the rig).
        module subroutine check_damping(self, sus, bod, stat)
            class(damping_group_t), intent(in) :: self
            type(suspension_group_t), intent(in) :: sus     !! the suspension, normalised
            type(body_group_t), intent(in) :: bod
            type(status_t), intent(inout) :: stat
        end subroutine check_damping
    end interface

contains

    ! ------------------------------------------------------------------ &suspension

    function suspension_name() result(s)
        character(len=:), allocatable :: s
        s = 'suspension'
    end function suspension_name

    function suspension_spec() result(s)
        character(len=:), allocatable :: s
        s = 'b:r1 b_prime:r1 l:r1 l_prime:r1 g:r1 cables:i1 radius:r1 radius_prime:r1 '// &
            'support_points:r'//itoa(3*MAX_CABLES)//' body_points:r'//itoa(3*MAX_CABLES)// &
            ' lengths:r'//itoa(MAX_CABLES)
    end function suspension_spec

    !> &suspension b, b_prime, l, l_prime, g, cables, radius, radius_prime, support_points,
    !! body_points, lengths.
    subroutine read_suspension(self, rec, ios, msg)
        class(suspension_group_t), intent(inout) :: self    !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: b, b_prime, l, l_prime, g, radius, radius_prime
        real(dp) :: support_points(3, MAX_CABLES), body_points(3, MAX_CABLES)
        real(dp) :: lengths(MAX_CABLES)
        integer :: cables
        namelist /suspension/ b, b_prime, l, l_prime, g, cables, radius, radius_prime, &
            support_points, body_points, lengths
        support_points = self%support_points
        body_points = self%body_points
        lengths = self%lengths
        b = NOT_GIVEN
        b_prime = NOT_GIVEN
        l = NOT_GIVEN
        l_prime = NOT_GIVEN
        g = NOT_GIVEN
        radius = NOT_GIVEN
        radius_prime = NOT_GIVEN
        cables = -huge(1)
        read (rec, nml=suspension, iostat=ios, iomsg=msg)
        call take('b', b, self%b)
        call take('b_prime', b_prime, self%b_prime)
        call take('l', l, self%l)
        call take('l_prime', l_prime, self%l_prime)
        call take('g', g, self%g)
        call take('radius', radius, self%radius)
        call take('radius_prime', radius_prime, self%radius_prime)
        if (cables /= -huge(1)) then
            self%cables = cables
            call self%note_given('cables')
        end if
        if (any(support_points /= self%support_points)) call self%note_given('support_points')
        if (any(body_points /= self%body_points)) call self%note_given('body_points')
        if (any(lengths /= self%lengths)) call self%note_given('lengths')
        self%support_points = support_points
        self%body_points = body_points
        self%lengths = lengths
    contains
        subroutine take(name, v, x)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: v
            real(dp), intent(inout) :: x
            if (v == NOT_GIVEN) return
            x = v
            call self%note_given(name)
        end subroutine take
    end subroutine read_suspension

    function echo_suspension(self) result(line)
        class(suspension_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        integer :: i, n
        line = '# &suspension b = '//rshort(self%b)//', b_prime = '//rshort(self%b_prime)// &
            ', l = '//rshort(self%l)//', l_prime = '//rshort(self%l_prime)//', g = '// &
            rshort(self%g)
        if (self%cables /= 2 .and. self%pointwise()) then
            n = min(max(self%cables, 0), MAX_CABLES)
            line = line//', cables = '//itoa(self%cables)
            do i = 1, n
                line = line//', support_points(:,'//itoa(i)//') = '// &
                    rlist_short(self%support_points(:, i))
            end do
            do i = 1, n
                line = line//', body_points(:,'//itoa(i)//') = '// &
                    rlist_short(self%body_points(:, i))
            end do
            line = line//', lengths = '//rlist_short(self%lengths(1:n))
        else if (self%cables /= 2) then
            line = line//', cables = '//itoa(self%cables)//', radius = '// &
                rshort(self%radius)//', radius_prime = '//rshort(self%radius_prime)
        end if
        line = line//' /'
    end function echo_suspension

    !> True when a platform is given point by point (support_points, body_points, lengths).
    pure logical function pointwise(self)
        class(suspension_group_t), intent(in) :: self
        pointwise = self%gave('support_points') .or. self%gave('body_points') .or. &
                    self%gave('lengths')
    end function pointwise

    !> A platform of 3 or more cables as its equivalent pair: b = 2 radius,
    !! b_prime = 2 radius_prime, every cable of length l; given point by point, b and
    !! b_prime twice the mean distance of the support's and the body's points from their
    !! centroids, l = l_prime the mean length (the scales the deck's checks take).
    pure subroutine normalise_suspension(self)
        class(suspension_group_t), intent(inout) :: self
        integer :: n, i
        real(dp) :: cs(3), cb(3), ds, db
        if (self%cables <= 2) return
        if (self%pointwise()) then
            n = min(self%cables, MAX_CABLES)
            cs = [(sum(self%support_points(i, 1:n))/n, i = 1, 3)]
            cb = [(sum(self%body_points(i, 1:n))/n, i = 1, 3)]
            ds = 0.0_dp
            db = 0.0_dp
            do i = 1, n
                ds = ds + norm2(self%support_points(:, i) - cs)
                db = db + norm2(self%body_points(:, i) - cb)
            end do
            self%b = 2.0_dp*ds/n
            self%b_prime = 2.0_dp*db/n
            self%l = sum(self%lengths(1:n))/n
            self%l_prime = self%l
            return
        end if
        self%b = 2.0_dp*self%radius
        self%b_prime = 2.0_dp*self%radius_prime
        self%l_prime = self%l
    end subroutine normalise_suspension

    ! ------------------------------------------------------------------ &body

    function body_name() result(s)
        character(len=:), allocatable :: s
        s = 'body'
    end function body_name

    function body_spec() result(s)
        character(len=:), allocatable :: s
        s = 'mass:r1 inertia:r3 r:r1 lambda:r1 cg_depth:r1 cg_offset:r2 btilde:r9 sway_depth:r1 '// &
            'size:r1'
    end function body_spec

    !> &body mass, inertia, r, lambda, cg_depth, cg_offset (one value on a bifilar, two on a
    !! platform: its second is cg_offset_y, tracked as given apart), btilde, sway_depth, size.
    subroutine read_body(self, rec, ios, msg)
        class(body_group_t), intent(inout) :: self  !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: mass, inertia(3), r, lambda, cg_depth, cg_offset(2), btilde(3, 3), &
                    sway_depth, size
        namelist /body/ mass, inertia, r, lambda, cg_depth, cg_offset, btilde, sway_depth, size
        mass = NOT_GIVEN
        size = NOT_GIVEN
        inertia = NOT_GIVEN
        r = NOT_GIVEN
        lambda = NOT_GIVEN
        cg_depth = NOT_GIVEN
        cg_offset = NOT_GIVEN
        btilde = self%btilde
        sway_depth = self%sway_depth
        read (rec, nml=body, iostat=ios, iomsg=msg)
        call take('mass', mass, self%mass)
        call take('r', r, self%r)
        call take('lambda', lambda, self%lambda)
        call take('cg_depth', cg_depth, self%cg_depth)
        call take('cg_offset', cg_offset(1), self%cg_offset)
        if (cg_offset(2) /= NOT_GIVEN) then
            self%cg_offset_y = cg_offset(2)
            call self%note_given('cg_offset')
            call self%note_given('cg_offset_y')
        end if
        call take('size', size, self%size)
        if (any(inertia /= NOT_GIVEN)) call self%note_given('inertia')
        where (inertia /= NOT_GIVEN) self%inertia = inertia
        self%btilde = btilde
        self%sway_depth = sway_depth
    contains
        subroutine take(name, v, x)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: v
            real(dp), intent(inout) :: x
            if (v == NOT_GIVEN) return
            x = v
            call self%note_given(name)
        end subroutine take
    end subroutine read_body

    function echo_body(self) result(line)
        class(body_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        integer :: i
        line = '# &body mass = '//rshort(self%mass)//', inertia = '// &
            rlist_short(self%inertia)//', r = '//rshort(self%r)//', lambda = '// &
            rshort(self%lambda)
        if (self%gave('cg_depth') .or. self%gave('cg_offset')) line = line// &
            ', cg_depth = '//rshort(self%cg_depth)//', cg_offset = '//rshort(self%cg_offset)
        if (self%gave('cg_offset_y')) line = line//', '//rshort(self%cg_offset_y)
        do i = 1, 3
            line = line//', btilde('//achar(iachar('0') + i)//',:) = '// &
                rlist_short(self%btilde(i, :))
        end do
        line = line//', sway_depth = '//rshort(self%sway_depth)
        if (self%gave('size')) line = line//', size = '//rshort(self%size)
        line = line//' /'
    end function echo_body

    !> True when the mass centre is given as measured (cg_depth, cg_offset; always on a
    !! platform): r and lambda then follow from it (centre).
    pure logical function centre_measured(self, sus)
        class(body_group_t), intent(in) :: self
        type(suspension_group_t), intent(in) :: sus     !! the suspension, normalised
        centre_measured = self%gave('cg_depth') .or. self%gave('cg_offset') .or. sus%cables > 2
    end function centre_measured

    !> The mass centre's r and lambda (eq. (21)) from cg_depth and cg_offset on the body's
    !! spacing b_prime: r cos(lambda) = b_prime/2 + cg_offset, r sin(lambda) = cg_depth.
    pure subroutine centre(self, b_prime, r, lambda)
        class(body_group_t), intent(in) :: self
        real(dp), intent(in) :: b_prime             !! the suspension's (normalised)
        real(dp), intent(out) :: r, lambda
        r = sqrt((0.5_dp*b_prime + self%cg_offset)**2 + self%cg_depth**2)
        lambda = atan2(self%cg_depth, 0.5_dp*b_prime + self%cg_offset)
    end subroutine centre

    !> The mass centre as r, lambda (from cg_depth, cg_offset when given so: centre), lambda
    !! reduced modulo 2 pi.
    pure subroutine normalise_body(self, sus)
        class(body_group_t), intent(inout) :: self
        type(suspension_group_t), intent(in) :: sus     !! the suspension, normalised
        real(dp) :: r, lambda
        if (self%centre_measured(sus)) then
            call self%centre(sus%b_prime, r, lambda)
            self%r = r
            self%lambda = lambda
        end if
        self%lambda = reduced(self%lambda)
    end subroutine normalise_body

    ! ------------------------------------------------------------------ &start

    function start_name() result(s)
        character(len=:), allocatable :: s
        s = 'start'
    end function start_name

    function start_spec() result(s)
        character(len=:), allocatable :: s
        s = 'mode:c1 amplitude:r1 tilt:r1 theta:r4 theta_dot:r4 sway:r1'
    end function start_spec

    !> &start mode, amplitude, tilt, theta, theta_dot, sway.
    subroutine read_start(self, rec, ios, msg)
        class(start_group_t), intent(inout) :: self !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        character(len=256) :: mode
        real(dp) :: amplitude, tilt, theta(4), theta_dot(4), sway
        namelist /start/ mode, amplitude, tilt, theta, theta_dot, sway
        sway = self%sway
        mode = self%mode
        amplitude = self%amplitude
        tilt = self%tilt
        theta = self%theta
        theta_dot = self%theta_dot
        read (rec, nml=start, iostat=ios, iomsg=msg)
        self%mode = mode
        self%amplitude = amplitude
        self%tilt = tilt
        self%theta = theta
        self%theta_dot = theta_dot
        self%sway = sway
    end subroutine read_start

    function echo_start(self) result(line)
        class(start_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &start mode = '//quoted(self%mode)//', amplitude = '// &
            rshort(self%amplitude)//', tilt = '//rshort(self%tilt)//', theta = '// &
            rlist_short(self%theta)//', theta_dot = '//rlist_short(self%theta_dot)
        if (self%sway /= 0.0_dp) line = line//', sway = '//rshort(self%sway)
        line = line//' /'
    end function echo_start

    !> mode in lower case; tilt and theta reduced modulo 2 pi into [-pi, pi] (the
    !! integrator's error control is relative: an angle of 1e6 rad would leave it a tolerance
    !! of rtol*1e6 rad).
    pure subroutine normalise_start(self)
        class(start_group_t), intent(inout) :: self
        self%mode = lower(adjustl(self%mode))
        self%tilt = reduced(self%tilt)
        self%theta = [reduced(self%theta(1)), reduced(self%theta(2)), reduced(self%theta(3)), &
                      reduced(self%theta(4))]
    end subroutine normalise_start

    ! ------------------------------------------------------------------ &integration

    function integration_name() result(s)
        character(len=:), allocatable :: s
        s = 'integration'
    end function integration_name

    function integration_spec() result(s)
        character(len=:), allocatable :: s
        s = 'tau_end:r1 dtau_out:r1 rtol:r1 atol:r1 error_estimate:l1 method:c1 '// &
            'sensitivities:c1 sensitivity_error_control:l1'
    end function integration_spec

    !> &integration tau_end, dtau_out, rtol, atol, error_estimate, method, sensitivities,
    !! sensitivity_error_control.
    subroutine read_integration(self, rec, ios, msg)
        class(integration_group_t), intent(inout) :: self   !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: tau_end, dtau_out, rtol, atol
        logical :: error_estimate, sensitivity_error_control
        character(len=256) :: method, sensitivities
        namelist /integration/ tau_end, dtau_out, rtol, atol, error_estimate, method, &
            sensitivities, sensitivity_error_control
        tau_end = self%tau_end
        dtau_out = self%dtau_out
        rtol = self%rtol
        atol = self%atol
        error_estimate = self%error_estimate
        method = self%method
        sensitivities = self%sensitivities
        sensitivity_error_control = self%sensitivity_error_control
        read (rec, nml=integration, iostat=ios, iomsg=msg)
        self%tau_end = tau_end
        self%dtau_out = dtau_out
        self%rtol = rtol
        self%atol = atol
        self%error_estimate = error_estimate
        self%method = method
        self%sensitivities = sensitivities
        self%sensitivity_error_control = sensitivity_error_control
    end subroutine read_integration

    function echo_integration(self) result(line)
        class(integration_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &integration tau_end = '//rshort(self%tau_end)//', dtau_out = '// &
            rshort(self%dtau_out)//', rtol = '//rshort(self%rtol)//', atol = '// &
            rshort(self%atol)//', error_estimate = '// &
            trim(merge('.true. ', '.false.', self%error_estimate))//', method = '// &
            quoted(self%method)//', sensitivities = '//quoted(self%sensitivities)// &
            ', sensitivity_error_control = '// &
            trim(merge('.true. ', '.false.', self%sensitivity_error_control))//' /'
    end function echo_integration

    !> method and sensitivities in lower case.
    pure subroutine normalise_integration(self)
        class(integration_group_t), intent(inout) :: self
        self%method = lower(adjustl(self%method))
        self%sensitivities = lower(adjustl(self%sensitivities))
    end subroutine normalise_integration

    ! ------------------------------------------------------------------ &cables

    function cables_name() result(s)
        character(len=:), allocatable :: s
        s = 'cables'
    end function cables_name

    function cables_spec() result(s)
        character(len=:), allocatable :: s
        s = 'stiffness:r1 damping:r1'
    end function cables_spec

    !> &cables stiffness, damping.
    subroutine read_cables(self, rec, ios, msg)
        class(cables_group_t), intent(inout) :: self    !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: stiffness, damping
        namelist /cables/ stiffness, damping
        stiffness = self%stiffness
        damping = self%damping
        read (rec, nml=cables, iostat=ios, iomsg=msg)
        self%stiffness = stiffness
        self%damping = damping
    end subroutine read_cables

    function echo_cables(self) result(line)
        class(cables_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &cables stiffness = '//rshort(self%stiffness)//', damping = '// &
            rshort(self%damping)//' /'
    end function echo_cables

    ! ------------------------------------------------------------------ &damping

    function damping_name() result(s)
        character(len=:), allocatable :: s
        s = 'damping'
    end function damping_name

    function damping_spec() result(s)
        character(len=:), allocatable :: s
        s = 'c_v:r1 c_q:r1'
    end function damping_spec

    !> &damping c_v, c_q.
    subroutine read_damping(self, rec, ios, msg)
        class(damping_group_t), intent(inout) :: self   !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: c_v, c_q
        namelist /damping/ c_v, c_q
        c_v = self%c_v
        c_q = self%c_q
        read (rec, nml=damping, iostat=ios, iomsg=msg)
        self%c_v = c_v
        self%c_q = c_q
    end subroutine read_damping

    function echo_damping(self) result(line)
        class(damping_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        line = '# &damping c_v = '//rshort(self%c_v)//', c_q = '//rshort(self%c_q)//' /'
    end function echo_damping

    ! ------------------------------------------------------------------ angles

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

end module rig_groups
