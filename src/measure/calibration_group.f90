!> The deck's group &calibration (analysis calibrate): what is known of the reference swung
!! on the rig, either a body of known moment (reference_I1, u_reference_I1) or a test mass
!! placed at known radii (test_mass, u_test_mass, test_radii: release k of the measurement
!! carries the test mass at test_radii(k) from the vertical axis, so that its moment grows
!! by test_mass r_k^2).  The swings themselves are given in &measurement, as identify takes
!! them.  Checked only when the analysis is requested.
module calibration_group
    use kinds, only: dp
    use status, only: status_t, STATUS_OK
    use text, only: rshort, rlist_short, itoa
    use deck_base, only: deck_group_t
    use value_checks, only: bad, finite
    implicit none
    private

    !> Most radii in &calibration test_radii.
    integer, parameter, public :: MAX_RADII = 100
    real(dp), parameter :: UNSET = -huge(1.0_dp)

    !> &calibration: the reference's known moment, or the test mass and its radii.
    type, extends(deck_group_t), public :: calibration_group_t
        real(dp) :: reference_i1 = 0.0_dp       !! the reference body's I1 (deck units; 0: none)
        real(dp) :: u_reference_i1 = 0.0_dp     !! its standard uncertainty
        real(dp) :: test_mass = 0.0_dp          !! the test mass (0: none)
        real(dp) :: u_test_mass = 0.0_dp        !! its standard uncertainty
        integer :: n_radii = 0                  !! radii given (test_radii(1:n_radii))
        real(dp) :: test_radii(MAX_RADII) = UNSET   !! each release's radius of the test mass
    contains
        procedure, nopass :: name => calibration_name
        procedure, nopass :: spec => calibration_spec
        procedure :: read_text => read_calibration_group
        procedure :: echo => echo_calibration
        procedure :: check => check_calibration
        procedure :: by_test_mass
    end type calibration_group_t

contains

    function calibration_name() result(s)
        character(len=:), allocatable :: s
        s = 'calibration'
    end function calibration_name

    function calibration_spec() result(s)
        character(len=:), allocatable :: s
        s = 'reference_i1:r1 u_reference_i1:r1 test_mass:r1 u_test_mass:r1 test_radii:r100'
    end function calibration_spec

    !> True when the reference is a test mass at radii (else a body of known moment).
    pure logical function by_test_mass(self)
        class(calibration_group_t), intent(in) :: self
        by_test_mass = self%test_mass > 0.0_dp
    end function by_test_mass

    subroutine read_calibration_group(self, rec, ios, msg)
        class(calibration_group_t), intent(inout) :: self   !! defaults in, values read out
        character(len=*), intent(in) :: rec         !! the group as one record
        integer, intent(out) :: ios                 !! iostat of the namelist read
        character(len=*), intent(inout) :: msg      !! iomsg of the namelist read
        real(dp) :: reference_i1, u_reference_i1, test_mass, u_test_mass
        real(dp) :: test_radii(MAX_RADII)
        integer :: k
        namelist /calibration/ reference_i1, u_reference_i1, test_mass, u_test_mass, test_radii
        reference_i1 = self%reference_i1
        u_reference_i1 = self%u_reference_i1
        test_mass = self%test_mass
        u_test_mass = self%u_test_mass
        test_radii = self%test_radii
        read (rec, nml=calibration, iostat=ios, iomsg=msg)
        self%reference_i1 = reference_i1
        self%u_reference_i1 = u_reference_i1
        self%test_mass = test_mass
        self%u_test_mass = u_test_mass
        self%test_radii = test_radii
        self%n_radii = 0
        do k = 1, MAX_RADII
            if (test_radii(k) == UNSET) exit
            self%n_radii = k
        end do
    end subroutine read_calibration_group

    function echo_calibration(self) result(line)
        class(calibration_group_t), intent(in) :: self
        character(len=:), allocatable :: line
        if (self%by_test_mass()) then
            line = '# &calibration test_mass = '//rshort(self%test_mass)//', u_test_mass = '// &
                rshort(self%u_test_mass)//', test_radii = '// &
                rlist_short(self%test_radii(1:self%n_radii))//' /'
        else
            line = '# &calibration reference_i1 = '//rshort(self%reference_i1)// &
                ', u_reference_i1 = '//rshort(self%u_reference_i1)//' /'
        end if
    end function echo_calibration

    !> The reference: a known moment (> 0, u >= 0) or a test mass (> 0, u >= 0) with at
    !! least two radii (>= 0, not all equal), not both.
    subroutine check_calibration(self, stat)
        class(calibration_group_t), intent(in) :: self
        type(status_t), intent(inout) :: stat
        integer :: k
        call finite(stat, 'calibration', 'reference_i1', self%reference_i1)
        call finite(stat, 'calibration', 'u_reference_i1', self%u_reference_i1)
        call finite(stat, 'calibration', 'test_mass', self%test_mass)
        call finite(stat, 'calibration', 'u_test_mass', self%u_test_mass)
        do k = 1, self%n_radii
            call finite(stat, 'calibration', 'test_radii('//itoa(k)//')', self%test_radii(k))
        end do
        if (stat%code /= STATUS_OK) return
        if (self%reference_i1 > 0.0_dp .eqv. self%test_mass > 0.0_dp) then
            call bad(stat, 'calibration', 'reference_i1', rshort(self%reference_i1), &
                     'with test_mass = '//rshort(self%test_mass)//': give one reference', &
                     'reference_i1 > 0 (a body of known moment) or test_mass > 0 with '// &
                     'test_radii (a test mass at known radii), not both')
        else if (self%u_reference_i1 < 0.0_dp .or. self%u_reference_i1 >= self%reference_i1 &
                 .and. self%reference_i1 > 0.0_dp) then
            call bad(stat, 'calibration', 'u_reference_i1', rshort(self%u_reference_i1), &
                     'not a standard uncertainty of reference_i1', '0 <= u_reference_i1 < '// &
                     'reference_i1')
        else if (self%by_test_mass()) then
            if (self%u_test_mass < 0.0_dp .or. self%u_test_mass >= self%test_mass) then
                call bad(stat, 'calibration', 'u_test_mass', rshort(self%u_test_mass), &
                         'not a standard uncertainty of test_mass', '0 <= u_test_mass < '// &
                         'test_mass')
            else if (self%n_radii < 2) then
                call bad(stat, 'calibration', 'test_radii', itoa(self%n_radii)//' radii', &
                         'too few to give the slope dI1/d(r^2)', 'one radius per release, '// &
                         'at least two releases')
            else if (any(self%test_radii(1:self%n_radii) < 0.0_dp)) then
                call bad(stat, 'calibration', 'test_radii', &
                         rlist_short(self%test_radii(1:self%n_radii)), 'a negative radius', &
                         'radii >= 0')
            else if (maxval(self%test_radii(1:self%n_radii)) == &
                     minval(self%test_radii(1:self%n_radii))) then
                call bad(stat, 'calibration', 'test_radii', &
                         rlist_short(self%test_radii(1:self%n_radii)), 'all equal', &
                         'at least two different radii')
            end if
        end if
    end subroutine check_calibration

end module calibration_group
