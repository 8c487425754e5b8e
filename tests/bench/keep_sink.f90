!> A sink of the run loop that keeps the states at the requested times (bench_global_error).
module keep_sink
    use kinds, only: dp
    use status, only: status_t
    use run_loop, only: row_sink_t, stepped_model_t
    use unused_arg, only: unused
    implicit none
    private

    !> The states at the output times: ys(:, k) the state at times(k).
    type, extends(row_sink_t), public :: keep_t
        real(dp), allocatable :: ys(:, :)       !! (n, 0:rows), allocated by the caller
    contains
        procedure :: take => keep_take
    end type keep_t

contains

    !> Keep row k's state.
    subroutine keep_take(sink, m, k, t, y, stat)
        class(keep_t), intent(inout) :: sink
        class(stepped_model_t), intent(inout) :: m
        integer, intent(in) :: k                !! the row
        real(dp), intent(in) :: t               !! its time
        real(dp), intent(in) :: y(:)            !! the state there
        type(status_t), intent(out) :: stat
        call unused(m)
        call unused(t)
        stat%code = 0
        sink%ys(:, k) = y(1:size(sink%ys, 1))
    end subroutine keep_take

end module keep_sink
