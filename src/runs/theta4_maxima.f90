!> The maxima of theta4 in a run of the paper's model (a sink of the run loop): the one
!! definition of a period every measurement of periods uses (identify's simulated periods,
!! module period_inversion; a hang's period and the drift of its maxima, module
!! hang_model).
!!
!! A maximum is the first zero of theta4' going from + to - after theta4 has swung below
!! its rest value (0), located in the integrator's dense output by the Illinois variant of
!! regula falsi (run_loop's falling_zero) to roundoff; after each maximum theta4 must swing
!! below 0 again before the next counts.  The run ends at the `want`-th maximum.  From a
!! release at rest at theta4 = A the first maximum is one period later.
module theta4_maxima
    use kinds, only: dp
    use status, only: status_t
    use bifilar_model, only: NSTATE
    use run_loop, only: stepped_model_t, row_sink_t, falling_zero
    use unused_arg, only: unused
    implicit none
    private

    !> Finds the maxima of theta4 in the run loop (watch_steps must be .true.).
    type, extends(row_sink_t), public :: maxima_sink_t
        integer :: want = 1                     !! maxima to find (the run ends there)
        integer :: found = 0                    !! maxima found so far
        logical :: below = .false.              !! theta4 has been below 0 since the last
        real(dp), allocatable :: t(:)           !! (want) their times (tau)
        real(dp), allocatable :: a(:)           !! (want) theta4 at each (rad)
    contains
        procedure :: take => maxima_take
        procedure :: after_step => maxima_after_step
    end type maxima_sink_t

contains

    !> maxima_sink_t takes no rows.
    subroutine maxima_take(sink, m, k, t, y, stat)
        class(maxima_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        type(status_t), intent(out) :: stat
        call unused(sink)
        call unused(m)
        call unused(k)
        call unused(t)
        call unused(y)
        stat%code = 0
    end subroutine maxima_take

    !> After a step [t0, t1]: note theta4 below 0; after that, a theta4' going from + to -
    !! within the step is a maximum, located on the dense output to roundoff.
    subroutine maxima_after_step(sink, m, t0, t1, stat)
        class(maxima_sink_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        real(dp), intent(in) :: t0, t1          !! the step
        type(status_t), intent(out) :: stat
        real(dp) :: y(NSTATE), c
        logical :: found
        if (.not. sink%below) then
            call m%state_at(t1, y, stat)
            if (stat%code /= 0) return
            sink%below = y(4) < 0.0_dp
            return
        end if
        call falling_zero(m, t0, t1, 9, found, c, y, stat)
        if (stat%code /= 0 .or. .not. found) return
        if (.not. allocated(sink%t)) allocate (sink%t(max(1, sink%want)), &
                                               sink%a(max(1, sink%want)))
        sink%found = sink%found + 1
        sink%t(sink%found) = c
        sink%a(sink%found) = y(4)
        sink%below = .false.
        sink%done = sink%found >= sink%want
    end subroutine maxima_after_step

end module theta4_maxima
