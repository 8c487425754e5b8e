!> Sweeps of independent points: the parallel loop shared by the stability chart and the rig
!! design (and, with MPI, by ranks).
!!
!! A sweep is n points, each computed from its index alone by one routine that returns a
!! fixed number of reals: `work%point(k, vals)`.  The points do not talk to each other and
!! the work object is read only (intent(in)), so they may be computed in any order, by any
!! thread or process; `run_sweep` stores point k's values in column k of one array, so the
!! result, and every file made from it, is the same whatever the order.  A failure of a
!! point is a value (a sentinel such as -1 or -2 chosen by the work), never a stop: a sweep
!! always completes.
!!
!! This is the shape a distributed sweep needs (issue 15): ranks take indices from a shared
!! counter (dynamic work sharing), send back (k, vals) pairs, and a checkpoint is the list of
!! completed pairs; `run_sweep` is the shared-memory version, OpenMP with dynamic scheduling
!! one point at a time (OMP_NUM_THREADS is honoured), with one line of progress on a
!! terminal (module progress).
module sweep
    use kinds, only: dp
    use progress, only: progress_t
    implicit none
    private

    !> The points of a sweep: extend it with the data the points need and a `point` routine.
    type, abstract, public :: sweep_work_t
    contains
        procedure(sweep_point_i), deferred :: point
    end type sweep_work_t

    abstract interface
        !> The values of point k (1 <= k <= number of points), from k alone; must not
        !! change shared state (it runs on many threads at once).
        subroutine sweep_point_i(work, k, vals)
            import :: sweep_work_t, dp
            class(sweep_work_t), intent(in) :: work     !! the sweep's data
            integer, intent(in) :: k                    !! point index
            real(dp), intent(out) :: vals(:)            !! its values (sentinels on failure)
        end subroutine sweep_point_i
    end interface

    public :: run_sweep

contains

    !> Compute every point of the sweep: vals(:, k) = point k, for k = 1 .. size(vals, 2), in
    !! parallel (OpenMP, dynamic scheduling, one point at a time: points may differ in cost
    !! by orders of magnitude).  `label` names the work on the progress line ('' for none).
    subroutine run_sweep(work, vals, label, wall_seconds)
        class(sweep_work_t), intent(in) :: work     !! the points
        real(dp), intent(out) :: vals(:, :)         !! (values per point, points)
        character(len=*), intent(in) :: label       !! progress label, e.g. 'box: chart'
        real(dp), intent(out), optional :: wall_seconds   !! elapsed time of the sweep (s)
        type(progress_t) :: pr
        integer :: k, n, c0, c1, crate
        n = size(vals, 2)
        if (len(label) > 0) call pr%start(label, n)
        call system_clock(c0, crate)
        !$omp parallel do schedule(dynamic, 1) default(none) shared(work, vals, n, pr, label) &
        !$omp private(k)
        do k = 1, n
            call work%point(k, vals(:, k))
            if (len(label) > 0) then
                !$omp critical (sweep_progress)
                call pr%tick()
                !$omp end critical (sweep_progress)
            end if
        end do
        !$omp end parallel do
        if (len(label) > 0) call pr%finish()
        call system_clock(c1)
        if (present(wall_seconds)) wall_seconds = real(c1 - c0, dp)/real(crate, dp)
    end subroutine run_sweep

end module sweep
