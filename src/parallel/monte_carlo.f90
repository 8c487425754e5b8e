!> Monte Carlo of independent samples as a sweep (GUM Supplement 1, JCGM 101:2008):
!! the one Monte Carlo code path of the program (identify's, from periods and
!! from a record; tensor's, from the periods of several hangs).
!!
!! Sample k (1 .. n) draws its inputs from stream k of the seed (module random) and gives
!! a fixed number of estimates (`mc_task_t`, deferred `sample(k, est, stat)`), so the
!! samples are the points of a sweep (module sweep_engine): computed in any order, by any
!! thread of any rank, checkpointed (OUTDIR/NAME.identify_mc.partial) and resumed with
!! --resume, their estimates stored by k.  A point's values are the sample's estimates and
!! its status code (0: the sample succeeded), so a failed sample does not stop the sweep:
!! afterwards the first failed sample (the smallest k, whatever the order of computing) is
!! computed again on rank 0 for its message, and the Monte Carlo fails with it (the
!! checkpoint is removed: the failure would repeat).  Otherwise the mean and the standard
!! deviation of each estimate over the samples, summed in the order of k, come out the
!! same bits on any number of ranks and threads.
!!
!! The other ranks of an MPI run build the same task from the deck and the sweep's payload
!! (module identify, identify_mc_task; module tensor, tensor_sweep_task).
module monte_carlo
    use kinds, only: dp
    use finite, only: finite_bits
    use status, only: status_t, set_error, STATUS_OK
    use text, only: itoa
    use deck_base, only: deck_source_t
    use output_io, only: out_files_t, remove_file
    use sweep_engine, only: sweep_task_t, sweep_run, sweep_options_t, sweep_report_t, &
        checkpoint_path
    implicit none
    private

    public :: monte_carlo_run

    !> The sweep's analysis name (its checkpoint: OUTDIR/NAME.identify_mc.partial).
    character(len=*), parameter, public :: MC_ANALYSIS = 'identify_mc'
    !> The sweep of analysis tensor's Monte Carlo (OUTDIR/NAME.tensor_mc.partial).
    character(len=*), parameter, public :: MC_TENSOR = 'tensor_mc'

    !> The samples of a Monte Carlo: extend it with what a sample needs and a `sample`.
    type, abstract, extends(sweep_task_t), public :: mc_task_t
        integer :: nest = 1                     !! estimates per sample
    contains
        procedure(mc_sample_i), deferred :: sample
        procedure :: compute => mc_compute
        procedure :: accepts => mc_accepts
    end type mc_task_t

    abstract interface
        !> The estimates of sample k from k alone (runs on many threads at once: must not
        !! change shared state).  A failed sample returns its status; est is then not used.
        subroutine mc_sample_i(self, k, est, stat)
            import :: mc_task_t, dp, status_t
            class(mc_task_t), intent(in) :: self    !! the Monte Carlo's data
            integer, intent(in) :: k                !! sample number, 1 .. n
            real(dp), intent(out) :: est(:)         !! its estimates (nest)
            type(status_t), intent(out) :: stat     !! the sample's failure
        end subroutine mc_sample_i
    end interface

contains

    !> Sample k as a sweep point: values = its estimates (0 when it failed), then its status
    !! code.  Never fails itself.
    subroutine mc_compute(self, i, values, stat)
        class(mc_task_t), intent(in) :: self
        integer, intent(in) :: i                !! sample number
        real(dp), intent(out) :: values(:)      !! nest estimates, status code
        type(status_t), intent(out) :: stat     !! always OK
        type(status_t) :: st
        call self%sample(i, values(1:self%nest), st)
        values(self%nest + 1) = real(st%code, dp)
        if (st%code /= STATUS_OK) values(1:self%nest) = 0.0_dp
        stat%code = STATUS_OK
    end subroutine mc_compute

    !> Sample i's values as read back from a checkpoint: a sample that succeeded (status 0)
    !! with finite estimates.  A failed sample is not taken from a checkpoint: it is
    !! computed again (the run then fails with its own message, or it does not fail).
    logical function mc_accepts(self, i, values) result(ok)
        class(mc_task_t), intent(in) :: self
        integer, intent(in) :: i                !! sample number
        real(dp), intent(in) :: values(:)       !! nest estimates, status code
        ok = size(values) == self%nest + 1 .and. i >= 1
        if (ok) ok = all(finite_bits(values))
        if (ok) ok = values(self%nest + 1) == 0.0_dp
    end function mc_accepts

    !> Run the n samples of `task` over the ranks and threads: the mean and standard
    !! deviation (divisor n - 1) of each estimate, or the failure of the first failed
    !! sample.  With `outdir` the sweep is checkpointed there (OUTDIR/NAME.identify_mc
    !! .partial; options: --resume, the interval) and draws a progress line on a terminal;
    !! `payload` is what the other ranks need beyond the deck to build the same task (see
    !! sweep_run); `analysis`: the sweep's name (MC_ANALYSIS, the default, or MC_TENSOR),
    !! which names its checkpoint.  `files` is not needed any more (module signals removes
    !! the run's temporary files on a signal, whatever the stage); callers may still pass it.
    subroutine monte_carlo_run(task, d, n, payload, mean, sdev, stat, outdir, options, &
                               report, files, analysis)
        class(mc_task_t), intent(in) :: task    !! the samples
        class(deck_source_t), intent(in) :: d   !! the deck's source (its path, name, text)
        integer, intent(in) :: n                !! samples (>= 2)
        real(dp), intent(in) :: payload(:)      !! for the other ranks (may be empty)
        real(dp), intent(out) :: mean(:), sdev(:)   !! of each estimate (nest)
        type(status_t), intent(out) :: stat     !! the first failed sample's, or the sweep's
        character(len=*), intent(in), optional :: outdir    !! checkpoints' folder
        type(sweep_options_t), intent(in), optional :: options
        type(sweep_report_t), intent(out), optional :: report
        type(out_files_t), intent(in), optional :: files
        character(len=*), intent(in), optional :: analysis
        real(dp), allocatable :: vals(:, :), s(:), est(:)
        character(len=:), allocatable :: ckpt, label, path, sweep
        integer :: k, j, nv, code
        mean = 0.0_dp
        sdev = 0.0_dp
        nv = task%nest + 1
        ckpt = ''
        label = ''
        path = ''
        if (allocated(d%path)) path = d%path
        sweep = MC_ANALYSIS
        if (present(analysis)) sweep = analysis
        if (present(outdir)) then
            ckpt = checkpoint_path(outdir, d%name, sweep)
            label = d%name//': '//sweep(1:index(sweep, '_mc', back=.true.) - 1)// &
                ' (Monte Carlo)'
        end if
        if (present(files)) continue
        call sweep_run(task, sweep, path, ckpt, label, n, nv, vals, stat, options, &
                       report, payload, d%text)
        if (stat%code /= STATUS_OK) return
        if (.not. allocated(vals)) return           ! (sweep_run fills it when it succeeds)
        k = findloc(vals(nv, :) /= 0.0_dp, .true., 1)
        if (k > 0) then
            ! the first failed sample again, here, for its message
            code = nint(vals(nv, k))
            allocate (est(task%nest))
            call task%sample(k, est, stat)
            if (stat%code == STATUS_OK) call set_error(stat, code, &
                'Monte Carlo sample '//itoa(k)//' failed (status '//itoa(code)// &
                ') on another rank and not here')
            if (len(ckpt) > 0) call remove_file(ckpt)
            return
        end if
        do j = 1, task%nest
            s = vals(j, :)
            mean(j) = sum(s)/n
            sdev(j) = sqrt(sum((s - mean(j))**2)/(n - 1))
        end do
    end subroutine monte_carlo_run

end module monte_carlo
