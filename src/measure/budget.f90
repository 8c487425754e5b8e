!> The uncertainty budget of a measurement (GUM, JCGM 100:2008): the standard uncertainties
!! of the inputs and one line of the budget per input.  The types every measurement
!! analysis shares; no computing here.
module budget
    use kinds, only: dp
    implicit none
    private

    !> Standard uncertainties of the inputs (deck units; period in s, amplitude in degrees);
    !! each >= 0, 0 when not known.
    type, public :: input_u_t
        real(dp) :: mass = 0.0_dp, l = 0.0_dp, l_prime = 0.0_dp, b = 0.0_dp, b_prime = 0.0_dp
        real(dp) :: g = 0.0_dp, period = 0.0_dp, amplitude = 0.0_dp
    end type input_u_t

    !> One line of an uncertainty budget.
    type, public :: budget_row_t
        character(len=24) :: input = ''         !! e.g. mass, l, period(2)
        real(dp) :: value = 0.0_dp              !! the input's value (deck units)
        real(dp) :: u = 0.0_dp                  !! its standard uncertainty
        real(dp) :: sensitivity = 0.0_dp        !! dI1/dx
        real(dp) :: contribution = 0.0_dp       !! |sensitivity| u
    end type budget_row_t

end module budget
