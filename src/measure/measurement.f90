!> The one model of a measurement: what was observed, on which rig, in which release and
!! session.  identify's periods, records and tables of releases, tensor's hangs and the
!! tares are read into it (module measurement_read); the analyses take their data from it.
!!
!! * An observation (observation_t) is one of: a timing (OBS_TIMING: the total time of
!!   `cycles` cycles at a mean peak amplitude, the period per cycle divided once, when it
!!   is read), a record of the swing (OBS_RECORD: its file, then the record itself and its
!!   CRC-64 once read), a timing of a hang (OBS_HANG: as a timing, of the body hung in its
!!   release's pose), a tare (OBS_TARE: a moment of inertia measured apart and subtracted,
!!   or a known one added).  Each belongs to a release (its index; 0 for a tare, which
!!   belongs to the whole measurement) and names its line in the table (0: the deck).
!! * A release (release_t) is one release of the body on one rig: its label, its session,
!!   its rig (rig_t: the deck's, with the inputs the release gave itself, own), its start,
!!   the parameters its fit estimates, and for a hang the body's pose (hang_t).  A release
!!   that fails is marked skipped, with its failure, where the deck allows it.
!! * A measurement (measurement_t) holds the releases, their observations, the inputs
!!   common to every release with their standard uncertainties, and the tares.
!! No computing here beyond taking the observations of a release apart.
module measurement
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use text, only: itoa, quoted
    use rig_type, only: rig_t, start_t
    use budget, only: input_t
    use records, only: record_t
    implicit none
    private

    !> The kinds of an observation.
    integer, parameter, public :: OBS_TIMING = 1, OBS_RECORD = 2, OBS_HANG = 3, OBS_TARE = 4
    !> Each kind in words.
    character(len=6), parameter, public :: OBS_NAMES(4) = [character(len=6) :: 'timing', &
        'record', 'hang', 'tare']
    !> The rig's inputs a release may give itself, in the order of release_t%own.
    character(len=8), parameter, public :: RIG_COLUMNS(5) = [character(len=8) :: 'l', &
        'l_prime', 'b', 'b_prime', 'mass']

    !> The body's pose in a hang (analysis tensor; deck units): which body-frame direction
    !! points up at rest, which runs from the attachment point C toward D, the mass centre
    !! from CD, and the hang's suspension (the model's input, module hang_model).
    type, public :: hang_t
        integer :: id = 0                       !! the table's `hang` value
        integer :: line = 0                     !! the line of its first row in the table
        real(dp) :: up(3) = [0.0_dp, 0.0_dp, 1.0_dp]    !! unit, body frame: up at rest
        real(dp) :: along(3) = [1.0_dp, 0.0_dp, 0.0_dp] !! unit, body frame, normal to up: C to D
        real(dp) :: l = 1.0_dp, l_prime = 1.0_dp, b = 1.0_dp, b_prime = 1.0_dp
        real(dp) :: cg_depth = 0.5_dp, cg_offset = 0.0_dp   !! the mass centre below CD, along CD
        !> 2: a bifilar; 3: a platform of three cables (a regular polygon: b = 2 radius,
        !! b_prime = 2 radius_prime, every cable l), the body resting on it with `up` normal
        !! to the platform and `along` its x axis (from its centre toward body point 1);
        !! cg_depth, cg_offset and cg_offset_y the mass centre below, along x and along
        !! y = up x along from the centre of the platform's attachment points
        integer :: cables = 2
        real(dp) :: cg_offset_y = 0.0_dp
        !> l, l_prime, b, b_prime given by this hang's own columns (independent inputs of
        !! the hang), else the deck's (inputs common to every hang)
        logical :: own(4) = .false.
        !> the attitude at rest as measured (the table's gx, gy, gz or tilt): the direction
        !! of gravity in the body frame, unit; attitude = .false. when not given
        logical :: attitude = .false.
        real(dp) :: gravity(3) = 0.0_dp
    end type hang_t

    !> One observation.
    type, public :: observation_t
        integer :: kind = OBS_TIMING            !! OBS_*
        integer :: release = 0                  !! its release (index; 0: the measurement's)
        integer :: line = 0                     !! its line in the table (0: the deck)
        ! a timing (OBS_TIMING, OBS_HANG)
        real(dp) :: total = 0.0_dp              !! the time of `cycles` cycles as read (s)
        real(dp) :: cycles = 1.0_dp             !! the cycles it spans
        real(dp) :: period = 0.0_dp             !! per cycle: total/cycles (s)
        real(dp) :: amplitude = 0.0_dp          !! mean peak theta4 (degrees; hang: 0 small)
        real(dp) :: u_total = 0.0_dp            !! standard uncertainty of the total (s)
        real(dp) :: u_period = 0.0_dp           !! per cycle: u_total/cycles (s)
        ! a record (OBS_RECORD)
        character(len=:), allocatable :: file   !! its file (relative to the deck or table)
        logical :: have_record = .false.        !! rec and crc read (once, checked)
        type(record_t) :: rec                   !! the record as read
        integer(int64) :: crc = 0               !! its file's CRC-64 (bytes as read)
        ! a tare (OBS_TARE)
        character(len=16) :: name = ''          !! tare_I1, added_inertia
        real(dp) :: value = 0.0_dp              !! its moment (deck units)
        real(dp) :: u = 0.0_dp                  !! its standard uncertainty
        real(dp) :: mass = 0.0_dp               !! the fixture's mass (a tare)
        logical :: added = .false.              !! a known moment added, not a fixture
    end type observation_t

    !> One release of the body.
    type, public :: release_t
        character(len=:), allocatable :: label  !! its label ('1' for the deck's; a hang's id)
        character(len=:), allocatable :: session    !! its session ('' : none given)
        integer :: id = 0                       !! a hang's `hang` value
        integer :: line = 0                     !! its first row's line (0: the deck)
        type(rig_t) :: rig                      !! its rig: the deck's, with its own inputs
        !> the rig inputs it gave itself (RIG_COLUMNS: l, l_prime, b, b_prime, mass): its
        !! own, independent of the other releases'
        logical :: own(5) = .false.
        type(start_t) :: start                  !! its start (the deck's &start)
        character(len=:), allocatable :: estimate   !! the parameters its fit estimates
        type(hang_t) :: hang                    !! a hang's pose (tensor)
        logical :: skipped = .false.            !! left out (&measurement on_failure)
        character(len=:), allocatable :: failure    !! why, when skipped
    end type release_t

    !> A measurement: releases, their observations, the common inputs, the tares.
    type, public :: measurement_t
        !> how the releases are named in messages: the table's key ('' : the deck's own)
        character(len=:), allocatable :: source
        logical :: from_table = .false.         !! a table of releases (or of hangs)
        type(release_t), allocatable :: releases(:)
        type(observation_t), allocatable :: obs(:)
        !> the inputs common to every release (deck units) with their standard u
        type(input_t), allocatable :: inputs(:)
        type(observation_t), allocatable :: tares(:)    !! OBS_TARE
        logical :: points = .false.             !! hangs given by their attachment points
    contains
        procedure :: of_release
        procedure :: periods_of
        procedure :: amplitudes_of
        procedure :: cycles_of
        procedure :: u_periods_of
        procedure :: u_totals_of
        procedure :: record_of
        procedure :: n_skipped
        procedure :: named
    end type measurement_t

contains

    !> The indices of release i's observations, in their order.
    pure function of_release(m, i) result(k)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        integer, allocatable :: k(:)
        integer :: j
        k = pack([(j, j=1, size(m%obs))], m%obs%release == i)
    end function of_release

    !> Release i's timed periods, per cycle (s).
    pure function periods_of(m, i) result(v)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        real(dp), allocatable :: v(:)
        v = m%obs(m%of_release(i))%period
    end function periods_of

    !> Release i's amplitudes (degrees).
    pure function amplitudes_of(m, i) result(v)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        real(dp), allocatable :: v(:)
        v = m%obs(m%of_release(i))%amplitude
    end function amplitudes_of

    !> The cycles each of release i's timings spans.
    pure function cycles_of(m, i) result(v)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        real(dp), allocatable :: v(:)
        v = m%obs(m%of_release(i))%cycles
    end function cycles_of

    !> The standard uncertainty of each of release i's periods, per cycle (s).
    pure function u_periods_of(m, i) result(v)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        real(dp), allocatable :: v(:)
        v = m%obs(m%of_release(i))%u_period
    end function u_periods_of

    !> The standard uncertainty of each of release i's timed totals (s).
    pure function u_totals_of(m, i) result(v)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        real(dp), allocatable :: v(:)
        v = m%obs(m%of_release(i))%u_total
    end function u_totals_of

    !> The index of release i's record (0: it has none: timings).
    pure integer function record_of(m, i) result(k)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        integer :: j
        k = 0
        do j = 1, size(m%obs)
            if (m%obs(j)%release == i .and. m%obs(j)%kind == OBS_RECORD) then
                k = j
                return
            end if
        end do
    end function record_of

    !> The releases left out.
    pure integer function n_skipped(m)
        class(measurement_t), intent(in) :: m
        n_skipped = 0
        if (allocated(m%releases)) n_skipped = count(m%releases%skipped)
    end function n_skipped

    !> How release i is named in messages: "trial 'LABEL' (line L)" for a table's, ''
    !! for the deck's own.
    pure function named(m, i) result(s)
        class(measurement_t), intent(in) :: m
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        s = ''
        if (.not. m%from_table) return
        s = 'trial '//quoted(m%releases(i)%label)
        ! a segment of a record (record_split) has no line of its own
        if (m%releases(i)%line > 0) s = s//' (line '//itoa(m%releases(i)%line)//')'
    end function named

end module measurement
