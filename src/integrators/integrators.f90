!> The choice of integrator: which one a run uses, and making it.  Every integration of the
!! program is made here (new_integrator) and driven through the interface of module
!! ode_system (integrator_t), so every analysis honours &integration method the same way.
module integrators
    use ode_system, only: integrator_t
    use lsoda, only: lsoda_t
    use radau, only: radau_t
    implicit none
    private

    !> The integrators.
    integer, parameter, public :: SOLVER_LSODA = 1, SOLVER_RADAU = 2

    !> How derivatives of whole runs are taken (&integration sensitivities): forward
    !! sensitivities integrated with the state (the integrators' sens_init), or the paths of
    !! before, differences of whole runs (a record fit's Jacobian and budget) and the
    !! variational equations integrated with the orbit under the error control (Floquet).
    integer, parameter, public :: SENS_FORWARD = 1, SENS_DIFFERENCES = 2

    public :: new_integrator, integrator_for, sensitivities_for

contains

    !> A new integrator of kind `method` (SOLVER_LSODA or SOLVER_RADAU; anything else gives
    !! LSODA), ready for its init.
    subroutine new_integrator(method, it)
        integer, intent(in) :: method                       !! SOLVER_LSODA or SOLVER_RADAU
        class(integrator_t), allocatable, intent(out) :: it !! the integrator
        if (method == SOLVER_RADAU) then
            allocate (radau_t :: it)
        else
            allocate (lsoda_t :: it)
        end if
    end subroutine new_integrator

    !> The integrator for &integration method and &scene model: 'radau' or 'lsoda' as asked;
    !! 'auto': Radau IIA for model = 'elastic' (stiff, lightly damped cables), LSODA for the
    !! paper's model.
    pure integer function integrator_for(method, model) result(m)
        character(len=*), intent(in) :: method      !! 'auto', 'lsoda' or 'radau'
        character(len=*), intent(in) :: model       !! 'kane' or 'elastic'
        m = SOLVER_LSODA
        if (trim(method) == 'radau' .or. (trim(method) == 'auto' .and. &
                                          trim(model) == 'elastic')) m = SOLVER_RADAU
    end function integrator_for

    !> The way of &integration sensitivities: SENS_DIFFERENCES for 'differences', else
    !! SENS_FORWARD ('forward', the default).
    pure integer function sensitivities_for(word) result(m)
        character(len=*), intent(in) :: word        !! 'forward' or 'differences'
        m = SENS_FORWARD
        if (trim(word) == 'differences') m = SENS_DIFFERENCES
    end function sensitivities_for

end module integrators
