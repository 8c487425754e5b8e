!> The inputs of a measurement's uncertainty budget: every quantity of the rig the model
!! uses, with its value and standard uncertainty, and how to set it on a rig (set_input).
!!
!! The inputs: mass, l, l_prime (a platform of three or more cables: their one length,
!! `length`, which moves every cable), b, b_prime, g; the moments I2 and I3 (u_inertia); the
!! mass centre, as cg_depth and cg_offset when the deck gives it so (on a platform with the
!! mass centre off its axis along y, cg_offset_y too, with u_cg_offset), else as r and lambda;
!! the release amplitude where it is held (a record fit that does not estimate it).  A
!! change of b_prime moves the two body attachment points symmetrically: the mass centre
!! keeps its depth below, and its offset along, the midpoint of CD (rig's move_b_prime).
!! On a rig where pure torsion is exact (equal cables, the mass centre on the vertical
!! bisector of AB, b1 vertical), the period does not depend on I2, I3, the mass centre's
!! depth, and to first order not on its offset (the rig is mirror-symmetric): those inputs'
!! sensitivities are 0 by symmetry (no_effect_on_torsion).
module inputs
    use kinds, only: dp, deg
    use rig_groups, only: suspension_group_t, body_group_t, start_group_t
    use measure_groups, only: measurement_group_t
    use rig, only: rig_t, start_t, move_b_prime
    use budget, only: input_t
    implicit none
    private

    !> One input of a budget (module budget's type).
    public :: input_t

    public :: deck_inputs, set_input, input_value, no_effect_on_torsion

    !> The inputs of a deck's budget: from the groups (module deck_runs adds
    !! deck_inputs(deck, with_amplitude)).
    interface deck_inputs
        module procedure inputs_of_groups
    end interface deck_inputs

contains

    !> The inputs of the deck's budget, in a fixed order: mass, l, l_prime, b, b_prime, g,
    !! I2, I3, the mass centre (cg_depth, cg_offset or r, lambda), and the release amplitude
    !! when `with_amplitude` (a record fit that holds it).
    pure function inputs_of_groups(sus, bod, mea, sta, with_amplitude) result(x)
        type(suspension_group_t), intent(in) :: sus     !! the deck's, normalised
        type(body_group_t), intent(in) :: bod
        type(measurement_group_t), intent(in) :: mea
        type(start_group_t), intent(in) :: sta
        logical, intent(in) :: with_amplitude   !! add the release amplitude
        type(input_t), allocatable :: x(:)
        if (sus%cables > 2) then
            ! a platform: every cable of one length, measured as one
            x = [input_t('mass', bod%mass, mea%u_mass), input_t('length', sus%l, mea%u_l)]
        else
            x = [input_t('mass', bod%mass, mea%u_mass), input_t('l', sus%l, mea%u_l), &
                 input_t('l_prime', sus%l_prime, mea%u_l_prime)]
        end if
        x = [x, input_t('b', sus%b, mea%u_b), &
             input_t('b_prime', sus%b_prime, mea%u_b_prime), input_t('g', sus%g, mea%u_g), &
             input_t('I2', bod%inertia(2), mea%u_inertia(1)), &
             input_t('I3', bod%inertia(3), mea%u_inertia(2))]
        if (bod%centre_measured(sus)) then
            x = [x, input_t('cg_depth', bod%cg_depth, mea%u_cg_depth), &
                 input_t('cg_offset', bod%cg_offset, mea%u_cg_offset)]
            ! a platform's mass centre off its axis along y: u_cg_offset moves it too
            if (sus%cables > 2 .and. bod%cg_offset_y /= 0.0_dp) x = [x, &
                input_t('cg_offset_y', bod%cg_offset_y, mea%u_cg_offset)]
        else
            x = [x, input_t('r', bod%r, mea%u_r), input_t('lambda', bod%lambda, mea%u_lambda)]
        end if
        if (with_amplitude .and. .not. mea%estimated('amplitude') .and. &
            trim(sta%mode) == 'raised') x = [x, input_t('amplitude', sta%amplitude, &
                                                        mea%u_amplitude)]
    end function inputs_of_groups

    !> Set the input `name` of rig rg (or start st) to v.
    pure subroutine set_input(rg, st, name, v)
        type(rig_t), intent(inout) :: rg
        type(start_t), intent(inout) :: st
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: v
        real(dp) :: depth, offset
        select case (trim(name))
        case ('mass')
            rg%mass = v
        case ('l')
            rg%l = v
        case ('l_prime')
            rg%l_prime = v
        case ('length')
            rg%l = v
            rg%l_prime = v
        case ('b')
            rg%b = v
        case ('b_prime')
            call move_b_prime(rg, v)
        case ('g')
            rg%g = v
        case ('I2')
            rg%inertia(2) = v
        case ('I3')
            rg%inertia(3) = v
        case ('r')
            rg%r = v
        case ('lambda')
            rg%lambda = v
        case ('cg_depth', 'cg_offset')
            depth = rg%r*sin(rg%lambda)
            offset = rg%r*cos(rg%lambda) - 0.5_dp*rg%b_prime
            if (trim(name) == 'cg_depth') then
                depth = v
            else
                offset = v
            end if
            rg%r = sqrt((0.5_dp*rg%b_prime + offset)**2 + depth**2)
            rg%lambda = atan2(depth, 0.5_dp*rg%b_prime + offset)
        case ('cg_offset_y')
            rg%cg_offset_y = v
        case ('amplitude')
            st%amplitude = v
        end select
    end subroutine set_input

    !> The value of input `name` on rig rg (start st).
    pure real(dp) function input_value(rg, st, name) result(v)
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        character(len=*), intent(in) :: name
        select case (trim(name))
        case ('mass')
            v = rg%mass
        case ('l', 'length')
            v = rg%l
        case ('l_prime')
            v = rg%l_prime
        case ('b')
            v = rg%b
        case ('b_prime')
            v = rg%b_prime
        case ('g')
            v = rg%g
        case ('I2')
            v = rg%inertia(2)
        case ('I3')
            v = rg%inertia(3)
        case ('r')
            v = rg%r
        case ('lambda')
            v = rg%lambda
        case ('cg_depth')
            v = rg%r*sin(rg%lambda)
        case ('cg_offset')
            v = rg%r*cos(rg%lambda) - 0.5_dp*rg%b_prime
        case ('cg_offset_y')
            v = rg%cg_offset_y
        case default
            v = st%amplitude
        end select
    end function input_value

    !> True for the inputs whose first-order effect on the period of pure torsion is 0 (on
    !! a rig where pure torsion is exact): I2, I3 and the mass centre's place.
    pure logical function no_effect_on_torsion(name)
        character(len=*), intent(in) :: name
        select case (trim(name))
        case ('I2', 'I3', 'cg_depth', 'cg_offset', 'cg_offset_y', 'r', 'lambda')
            no_effect_on_torsion = .true.
        case default
            no_effect_on_torsion = .false.
        end select
    end function no_effect_on_torsion

end module inputs
