!> The inputs of a measurement's uncertainty budget: every quantity of the rig the model
!! uses, with its value and standard uncertainty, and how to set it on a rig (set_input).
!!
!! The inputs: mass, l, l_prime (a platform of three or more cables: their one length,
!! `length`, which moves every cable), b, b_prime, g; the moments I2 and I3 (u_inertia); the
!! mass centre, as cg_depth and cg_offset when the deck gives it so, else as r and lambda;
!! the release amplitude where it is held (a record fit that does not estimate it).  A
!! change of b_prime moves the two body attachment points symmetrically: the mass centre
!! keeps its depth below, and its offset along, the midpoint of CD (rig's move_b_prime).
!! On a rig where pure torsion is exact (equal cables, the mass centre on the vertical
!! bisector of AB, b1 vertical), the period does not depend on I2, I3, the mass centre's
!! depth, and to first order not on its offset (the rig is mirror-symmetric): those inputs'
!! sensitivities are 0 by symmetry (no_effect_on_torsion).
module inputs
    use kinds, only: dp, deg
    use deck, only: deck_t, deck_gave, estimated
    use rig, only: rig_t, start_t, move_b_prime
    implicit none
    private

    !> One input of a budget.
    type, public :: input_t
        character(len=16) :: name = ''          !! mass, l, ..., cg_depth, amplitude
        real(dp) :: value = 0.0_dp              !! deck units (amplitude: degrees)
        real(dp) :: u = 0.0_dp                  !! its standard uncertainty
    end type input_t

    public :: deck_inputs, set_input, input_value, no_effect_on_torsion

contains

    !> The inputs of the deck's budget, in a fixed order: mass, l, l_prime, b, b_prime, g,
    !! I2, I3, the mass centre (cg_depth, cg_offset or r, lambda), and the release amplitude
    !! when `with_amplitude` (a record fit that holds it).
    pure function deck_inputs(d, with_amplitude) result(x)
        type(deck_t), intent(in) :: d           !! the deck
        logical, intent(in) :: with_amplitude   !! add the release amplitude
        type(input_t), allocatable :: x(:)
        if (d%cables > 2) then
            ! a platform: every cable of one length, measured as one
            x = [input_t('mass', d%mass, d%u_mass), input_t('length', d%l, d%u_l)]
        else
            x = [input_t('mass', d%mass, d%u_mass), input_t('l', d%l, d%u_l), &
                 input_t('l_prime', d%l_prime, d%u_l_prime)]
        end if
        x = [x, input_t('b', d%b, d%u_b), &
             input_t('b_prime', d%b_prime, d%u_b_prime), input_t('g', d%g, d%u_g), &
             input_t('I2', d%inertia(2), d%u_inertia(1)), &
             input_t('I3', d%inertia(3), d%u_inertia(2))]
        if (deck_gave(d, 'cg_depth') .or. deck_gave(d, 'cg_offset') .or. d%cables > 2) then
            x = [x, input_t('cg_depth', d%cg_depth, d%u_cg_depth), &
                 input_t('cg_offset', d%cg_offset, d%u_cg_offset)]
        else
            x = [x, input_t('r', d%r, d%u_r), input_t('lambda', d%lambda, d%u_lambda)]
        end if
        if (with_amplitude .and. .not. estimated(d, 'amplitude') .and. &
            trim(d%mode) == 'raised') x = [x, input_t('amplitude', d%amplitude, d%u_amplitude)]
    end function deck_inputs

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
        case default
            v = st%amplitude
        end select
    end function input_value

    !> True for the inputs whose first-order effect on the period of pure torsion is 0 (on
    !! a rig where pure torsion is exact): I2, I3 and the mass centre's place.
    pure logical function no_effect_on_torsion(name)
        character(len=*), intent(in) :: name
        select case (trim(name))
        case ('I2', 'I3', 'cg_depth', 'cg_offset', 'r', 'lambda')
            no_effect_on_torsion = .true.
        case default
            no_effect_on_torsion = .false.
        end select
    end function no_effect_on_torsion

end module inputs
