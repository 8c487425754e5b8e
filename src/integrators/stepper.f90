!> One interface to the project's two integrators, LSODA (module lsoda) and Radau IIA
!! (module radau): the calls a driver that steps, reads the dense output and counts needs
!! (simulate for the paper's model, elastic_solver for the elastic one).  The integrator
!! is chosen at init (SOLVER_LSODA or SOLVER_RADAU); the counters come back in LSODA's
!! terms (lsoda_stats_t; for Radau: Newton failures as convergence failures, rejected
!! steps as error-test failures, method METHOD_RADAU of order 5).
module stepper
    use kinds, only: dp
    use status, only: status_t, set_error, LSODA_ERR_TOO_MUCH_ACCURACY, &
        RADAU_ERR_TOO_MUCH_ACCURACY, RADAU_ERR_STEP_TOO_SMALL, RADAU_ERR_ILLEGAL_INPUT
    use ode_system, only: ode_system_t
    use lsoda, only: lsoda_t, lsoda_stats_t
    use radau, only: radau_t, radau_stats_t, METHOD_RADAU
    implicit none
    private

    !> The integrators.
    integer, parameter, public :: SOLVER_LSODA = 1, SOLVER_RADAU = 2

    !> One integration by either integrator.
    type, public :: stepper_t
        private
        integer :: method = SOLVER_LSODA
        type(lsoda_t) :: ls
        type(radau_t) :: ra
    contains
        procedure :: init => st_init
        procedure :: step => st_step
        procedure :: integrate => st_integrate
        procedure :: dense => st_dense
        procedure :: stats => st_stats
        procedure :: solver => st_solver
    end type stepper_t

    public :: too_much_accuracy

contains

    !> Start an integration at (t0, y0) with the integrator `method` (as lsoda_t%init and
    !! radau_t%init: rtol, atol of size 1 or n, tcrit, h0).  LSODA only: start_bdf,
    !! nonstiff_only (see lsoda_t%init).
    subroutine st_init(s, sys, t0, y0, rtol, atol, stat, method, tcrit, h0, start_bdf, &
                       nonstiff_only)
        class(stepper_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: t0, y0(:), rtol, atol(:)
        type(status_t), intent(out) :: stat     !! the integrator's init's
        integer, intent(in) :: method           !! SOLVER_LSODA or SOLVER_RADAU
        real(dp), intent(in), optional :: tcrit !! no step goes past tcrit
        real(dp), intent(in), optional :: h0    !! first step to try (> 0; else estimated)
        logical, intent(in), optional :: start_bdf, nonstiff_only
        real(dp) :: tc, hh
        logical :: bdf, adams
        s%method = method
        tc = 0.0_dp
        if (present(tcrit)) tc = tcrit
        hh = 0.0_dp
        if (present(h0)) hh = h0
        bdf = .false.
        if (present(start_bdf)) bdf = start_bdf
        adams = .false.
        if (present(nonstiff_only)) adams = nonstiff_only
        if (method == SOLVER_RADAU) then
            if (present(tcrit) .and. hh > 0.0_dp) then
                call s%ra%init(sys, t0, y0, rtol, atol, stat, tcrit=tc, h0=hh)
            else if (present(tcrit)) then
                call s%ra%init(sys, t0, y0, rtol, atol, stat, tcrit=tc)
            else if (hh > 0.0_dp) then
                call s%ra%init(sys, t0, y0, rtol, atol, stat, h0=hh)
            else
                call s%ra%init(sys, t0, y0, rtol, atol, stat)
            end if
        else if (method == SOLVER_LSODA) then
            if (present(tcrit)) then
                call s%ls%init(sys, t0, y0, rtol, atol, stat, tcrit=tc, start_bdf=bdf, &
                               nonstiff_only=adams)
            else
                call s%ls%init(sys, t0, y0, rtol, atol, stat, start_bdf=bdf, &
                               nonstiff_only=adams)
            end if
        else
            call set_error(stat, RADAU_ERR_ILLEGAL_INPUT, 'stepper init: unknown integrator')
        end if
    end subroutine st_init

    !> One step (as lsoda_t%step, radau_t%step).
    subroutine st_step(s, sys, stat, tout)
        class(stepper_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: tout  !! before the first step: direction and scale
        if (s%method == SOLVER_RADAU) then
            if (present(tout)) then
                call s%ra%step(sys, stat, tout)
            else
                call s%ra%step(sys, stat)
            end if
        else
            if (present(tout)) then
                call s%ls%step(sys, stat, tout)
            else
                call s%ls%step(sys, stat)
            end if
        end if
    end subroutine st_step

    !> Steps to tout and the solution there (as lsoda_t%integrate, radau_t%integrate).
    subroutine st_integrate(s, sys, tout, y, stat)
        class(stepper_t), intent(inout) :: s
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: tout
        real(dp), intent(out) :: y(:)
        type(status_t), intent(out) :: stat
        if (s%method == SOLVER_RADAU) then
            call s%ra%integrate(sys, tout, y, stat)
        else
            call s%ls%integrate(sys, tout, y, stat)
        end if
    end subroutine st_integrate

    !> Solution (k = 0) or its derivative (k = 1) at t in the last step.
    subroutine st_dense(s, t, k, dky, stat)
        class(stepper_t), intent(in) :: s
        real(dp), intent(in) :: t
        integer, intent(in) :: k
        real(dp), intent(out) :: dky(:)
        type(status_t), intent(out) :: stat
        if (s%method == SOLVER_RADAU) then
            call s%ra%dense(t, k, dky, stat)
        else
            call s%ls%dense(t, k, dky, stat)
        end if
    end subroutine st_dense

    !> The counters in LSODA's terms (see the module header).
    function st_stats(s) result(st)
        class(stepper_t), intent(in) :: s
        type(lsoda_stats_t) :: st
        type(radau_stats_t) :: rs
        if (s%method /= SOLVER_RADAU) then
            st = s%ls%stats()
            return
        end if
        rs = s%ra%stats()
        st%steps = rs%steps
        st%rhs_evals = rs%rhs_evals
        st%jac_evals = rs%jac_evals
        st%lu_decomps = rs%lu_decomps
        st%conv_failures = rs%newton_failures
        st%error_test_failures = rs%rejected
        st%method_switches = 0
        st%method_last = METHOD_RADAU
        st%order_last = 5
        st%method_next = METHOD_RADAU
        st%order_next = 5
        st%h_last = rs%h_last
        st%h_next = rs%h_next
        st%t_current = rs%t_current
    end function st_stats

    !> The integrator in use (SOLVER_LSODA or SOLVER_RADAU).
    integer function st_solver(s)
        class(stepper_t), intent(in) :: s
        st_solver = s%method
    end function st_solver

    !> True when stat is an integrator's refusal of a tolerance below what the machine
    !! precision allows (LSODA), or a step size that fell below the roundoff of t (Radau).
    pure logical function too_much_accuracy(stat)
        type(status_t), intent(in) :: stat
        too_much_accuracy = stat%code == LSODA_ERR_TOO_MUCH_ACCURACY .or. &
                            stat%code == RADAU_ERR_TOO_MUCH_ACCURACY .or. &
                            stat%code == RADAU_ERR_STEP_TOO_SMALL
    end function too_much_accuracy

end module stepper
