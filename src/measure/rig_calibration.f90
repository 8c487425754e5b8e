!> A rig's calibration: the effective constants a reference swung on the rig gives (analysis
!! calibrate), their covariance, the file NAME.calibration that carries them, and how a
!! measuring deck takes them (&measurement calibration = 'FILE').
!!
!! The constants: an effective-length offset delta_l added to every cable's length, and a
!! scale s of the spacing product b b' (R R' on a platform), applied as b sqrt(s) and
!! b' sqrt(s).  To first order the period of torsion depends on l and b b' only through
!! b b' / l, so releases at one cable length determine s/(1 + delta_l/l) alone: delta_l is
!! then held at 0 and s carries both (`separable` false, the estimator's rank note kept).
!! A calibrated rig takes its lengths and spacings from the calibration: the taped values'
!! own u leave the budget, and the calibration's covariance enters it as one row (kind
!! ROW_CALIBRATION) with u^2 = c^T C c, c the sensitivities of I1 to (delta_l, s).
module rig_calibration
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_DECK
    use text, only: quoted
    use output_io, only: read_kv
    use rig, only: rig_t, move_b_prime
    use budget, only: input_t, budget_row_t, ROW_CALIBRATION
    use measure_groups, only: measurement_group_t
    use measurement, only: measurement_t, OBS_RECORD
    implicit none
    private

    !> The calibrated constants.
    type, public :: rig_calibration_t
        real(dp) :: delta_l = 0.0_dp            !! effective-length offset (deck length units)
        real(dp) :: scale = 1.0_dp              !! scale of b b' (R R')
        !> covariance of (delta_l, scale)
        real(dp) :: cov(2, 2) = 0.0_dp
        logical :: separable = .false.          !! delta_l estimated (else held at 0)
        !> the taped constants the calibration was made on (deck units)
        real(dp) :: l = 0.0_dp, b = 0.0_dp, b_prime = 0.0_dp
        real(dp) :: chi2 = 0.0_dp
        integer :: dof = 0
    end type rig_calibration_t

    public :: calibrated_rig, calibrate_inputs, calibration_u, read_calibration_file
    public :: calibration_sensitivities, calibrate_measurement, calibration_row

contains

    !> The rig with the calibration's constants in place of the taped ones.
    pure function calibrated_rig(cal, rg) result(rc)
        type(rig_calibration_t), intent(in) :: cal
        type(rig_t), intent(in) :: rg
        type(rig_t) :: rc
        rc = rg
        rc%l = rg%l + cal%delta_l
        rc%l_prime = rg%l_prime + cal%delta_l
        rc%b = rg%b*sqrt(cal%scale)
        call move_b_prime(rc, rg%b_prime*sqrt(cal%scale))
    end function calibrated_rig

    !> The budget's inputs of a calibrated rig: lengths and spacings at their calibrated
    !! values, their taped u removed (the calibration's row carries them).
    pure subroutine calibrate_inputs(cal, x)
        type(rig_calibration_t), intent(in) :: cal
        type(input_t), intent(inout) :: x(:)
        integer :: j
        do j = 1, size(x)
            select case (trim(x(j)%name))
            case ('l', 'l_prime', 'length')
                x(j)%value = x(j)%value + cal%delta_l
                x(j)%u = 0.0_dp
            case ('b', 'b_prime')
                x(j)%value = x(j)%value*sqrt(cal%scale)
                x(j)%u = 0.0_dp
            end select
        end do
    end subroutine calibrate_inputs

    !> The sensitivities of I1 to (delta_l, scale) from those to the inputs (names, dI1/dx,
    !! values): dI1/d delta_l = the sum over the lengths, dI1/ds = sum over b, b' of
    !! dI1/db b / (2 s).
    pure function calibration_sensitivities(cal, names, c, values) result(g)
        type(rig_calibration_t), intent(in) :: cal
        character(len=*), intent(in) :: names(:)
        real(dp), intent(in) :: c(:), values(:)
        real(dp) :: g(2)
        integer :: j
        g = 0.0_dp
        do j = 1, size(names)
            select case (trim(names(j)))
            case ('l', 'l_prime', 'length')
                g(1) = g(1) + c(j)
            case ('b', 'b_prime')
                g(2) = g(2) + c(j)*values(j)/(2.0_dp*cal%scale)
            end select
        end do
    end function calibration_sensitivities

    !> The standard uncertainty the calibration gives I1: (g^T C g)^(1/2).
    pure real(dp) function calibration_u(cal, g) result(u)
        type(rig_calibration_t), intent(in) :: cal
        real(dp), intent(in) :: g(2)
        u = sqrt(max(0.0_dp, dot_product(g, matmul(cal%cov, g))))
    end function calibration_u

    !> Read a NAME.calibration file (analysis calibrate's output).  key: the deck's key
    !! that names it, for the message.
    subroutine read_calibration_file(path, key, cal, stat)
        character(len=*), intent(in) :: path, key
        type(rig_calibration_t), intent(out) :: cal
        type(status_t), intent(inout) :: stat
        character(len=20), parameter :: KEYS(7) = [character(len=20) :: 'delta_l', 'scale', &
            'var_delta_l', 'var_scale', 'cov_delta_l_scale', 'delta_l_estimated', 'l']
        real(dp) :: v(size(KEYS))
        logical :: found
        integer :: j
        do j = 1, size(KEYS)
            call read_kv(path, trim(KEYS(j)), v(j), found)
            if (.not. found) then
                call set_error(stat, ERR_DECK, '&measurement '//key//' = '//quoted(path)// &
                    ': no number '''//trim(KEYS(j))//''' in it; allowed: a NAME.calibration '// &
                    'file written by analyses = ''calibrate''')
                return
            end if
        end do
        if (.not. (v(2) > 0.0_dp) .or. v(3) < 0.0_dp .or. v(4) < 0.0_dp) then
            call set_error(stat, ERR_DECK, '&measurement '//key//' = '//quoted(path)// &
                ': scale not positive or a negative variance; allowed: a NAME.calibration '// &
                'file written by analyses = ''calibrate''')
            return
        end if
        cal%delta_l = v(1)
        cal%scale = v(2)
        cal%cov = reshape([v(3), v(5), v(5), v(4)], [2, 2])
        cal%separable = v(6) > 0.5_dp
        cal%l = v(7)
    end subroutine read_calibration_file

    !> A measurement on a calibrated rig (&measurement calibration = 'FILE'): every
    !! release's rig and the common inputs take the calibrated constants.  Timed periods
    !! only: a record or a Monte Carlo is refused.
    subroutine calibrate_measurement(mea, m, stat)
        type(measurement_group_t), intent(in) :: mea    !! the deck's, normalised
        type(measurement_t), intent(inout) :: m
        type(status_t), intent(inout) :: stat
        type(rig_calibration_t) :: cal
        integer :: i
        if (any(m%obs%kind == OBS_RECORD) .or. mea%monte_carlo > 0) then
            call set_error(stat, ERR_DECK, '&measurement calibration = '// &
                quoted(trim(mea%calibration))//' with a record or monte_carlo > 0: a '// &
                'calibration serves timed periods; allowed: periods or a table of timed '// &
                'releases, monte_carlo = 0')
            return
        end if
        call read_calibration_file(mea%calibration_path, 'calibration', cal, stat)
        if (stat%code /= 0) return
        do i = 1, size(m%releases)
            m%releases(i)%rig = calibrated_rig(cal, m%releases(i)%rig)
        end do
        call calibrate_inputs(cal, m%inputs)
    end subroutine calibrate_measurement

    !> The budget's row of a calibration (kind ROW_CALIBRATION): value the scale, u its
    !! standard uncertainty, contribution (g^T C g)^(1/2) with the first-order
    !! sensitivities of I1 = i1 (I1 proportional to s b b' / (l + delta_l)):
    !! dI1/d delta_l = -I1/l, dI1/ds = I1/s, l the calibrated length.
    pure function calibration_row(cal, i1, l) result(row)
        type(rig_calibration_t), intent(in) :: cal
        real(dp), intent(in) :: i1, l
        type(budget_row_t) :: row
        real(dp) :: g(2)
        g = [-i1/l, i1/cal%scale]
        row%input = 'calibration'
        row%kind = ROW_CALIBRATION
        row%value = cal%scale
        row%u = sqrt(max(0.0_dp, cal%cov(2, 2)))
        row%contribution = calibration_u(cal, g)
        row%sensitivity = g(2)
        if (row%u > 0.0_dp) row%sensitivity = row%contribution/row%u
    end function calibration_row

end module rig_calibration
