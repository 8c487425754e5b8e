!> What every analysis is to the driver: the abstract type `analysis_t` that each analysis
!! of `&scene analyses` extends (in its interface module analyses/NAME.f90, the procedures
!! in its submodule NAME_impl.f90), and what the analyses' parts of the summary line share.
!! This module is not an analysis: every analysis may use it (tests/module_graph.sh), and
!! it uses none.
!!
!! An analysis owns its inputs and outputs.  For one run of a deck the driver (module
!! driver) takes a fresh object of every analysis of its registry (src/app/registry.f90)
!! and, for those the deck asks for:
!!
!! 1. `ready(d, stat)`: the preconditions, all of them before any computing (what the
!!    analysis reads there, a record say, it keeps for its run);
!! 2. `run(d, outdir, files, stat, options)`: the computing, its files into the run's
!!    `out_files_t`, what the summary needs kept in the object; the analyses whose
!!    `runs_first` is true (the long sweeps: chart, design) run before the others, so no
!!    file of the deck is staged while they run;
!! 3. `summary(d)`: its part of the deck's summary line, ' WORD ...;', in the registry's
!!    order;
!! 4. `warnings`: the lines the run leaves for standard error (a sweep's checkpoint that
!!    could not be written, a suspicious result that stands), printed once the deck's files
!!    are committed;
!! 5. `owned_extensions(ext)`: the files NAME.EXT it may write, so that a commit removes
!!    those of an earlier run that this run did not write; `checkpoints(outdir, name)`: its
!!    sweeps' checkpoints, removed once the files are committed.
!!
!! In an MPI run the other ranks build a sweep's task from its name: the analysis whose
!! `sweeps(names)` holds the name gives it (`sweep_task`).
module analysis_base
    use kinds, only: dp
    use status, only: status_t, ERR_DECK
    use text, only: itoa
    use unused_arg, only: unused
    use deck, only: deck_t, analysis_requested
    use output_io, only: out_files_t
    use sweep_engine, only: sweep_task_t, sweep_options_t, sweep_report_t, checkpoint_path
    implicit none
    private

    public :: ranks_note, resume_note

    !> Longest word, file extension or sweep name of an analysis.
    integer, parameter, public :: WORD_LEN = 32

    !> One line of warning (stderr, exit 0).
    type, public :: warning_t
        character(len=:), allocatable :: s
    end type warning_t

    !> An analysis as the driver sees it.
    type, abstract, public :: analysis_t
        !> the run's warnings, one line each, for standard error once the files are committed
        type(warning_t), allocatable :: warnings(:)
    contains
        !> its word in &scene analyses
        procedure(word_i), deferred, nopass :: word
        !> the files it may write: OUTDIR/NAME followed by each of these
        procedure(words_i), deferred, nopass :: owned_extensions
        !> the names of its sweeps (checkpoints OUTDIR/NAME.SWEEP.partial; the other ranks
        !! of an MPI run build a task by this name); the default: none
        procedure, nopass :: sweeps => no_sweeps
        !> whether it runs before the analyses without it; the default: in its turn
        procedure, nopass :: runs_first => in_turn
        procedure(ready_i), deferred :: ready
        procedure(run_i), deferred :: run
        procedure(summary_i), deferred :: summary
        !> the task of its sweep `sweep` on the other ranks; the default: ERR_DECK
        procedure :: sweep_task => no_sweep_task
        procedure, non_overridable :: requested
        procedure, non_overridable :: checkpoints
        procedure, non_overridable :: add_warning
        procedure, non_overridable :: add_report_warning
    end type analysis_t

    !> One analysis of the registry.
    type, public :: analysis_slot_t
        class(analysis_t), allocatable :: a
    end type analysis_slot_t

    abstract interface
        !> A word of the analysis.
        function word_i() result(w)
            character(len=:), allocatable :: w
        end function word_i

        !> A list of words of the analysis (file extensions, sweep names).  (A subroutine:
        !! gfortran 12 fails on a type-bound function whose result is an array of strings.)
        subroutine words_i(names)
            import :: WORD_LEN
            character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        end subroutine words_i

        !> The preconditions, checked before any computing: a failure names the deck's
        !! variable, what is wrong and what is allowed.  What it read is kept for the run.
        subroutine ready_i(self, d, stat)
            import :: analysis_t, deck_t, status_t
            class(analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_MODEL
        end subroutine ready_i

        !> The run (after ready): its files into `files` (the driver commits them together
        !! with the others, or removes them all on a failure), its results kept for summary.
        subroutine run_i(self, d, outdir, files, stat, options)
            import :: analysis_t, deck_t, out_files_t, status_t, sweep_options_t
            class(analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck (ready passed)
            character(len=*), intent(in) :: outdir  !! output folder
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! the first failure
            type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
        end subroutine run_i

        !> Its part of the deck's summary line after a run: ' WORD ...;'.
        function summary_i(self, d) result(s)
            import :: analysis_t, deck_t
            class(analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck the run took
            character(len=:), allocatable :: s
        end function summary_i
    end interface

contains

    !> No sweep.
    subroutine no_sweeps(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        allocate (names(0))
    end subroutine no_sweeps

    !> In its turn.
    logical function in_turn()
        in_turn = .false.
    end function in_turn

    !> No sweep of that name (the analysis has no sweep).
    subroutine no_sweep_task(self, sweep, d, payload, task, stat)
        class(analysis_t), intent(in) :: self
        character(len=*), intent(in) :: sweep       !! the sweep's name (its job's analysis)
        type(deck_t), intent(in) :: d               !! the deck
        real(dp), intent(in) :: payload(:)          !! the sweep's payload
        class(sweep_task_t), allocatable, intent(out) :: task
        type(status_t), intent(out) :: stat         !! ERR_DECK
        call unused(d)
        call unused(payload)
        stat%code = ERR_DECK
        stat%msg = 'analysis '//self%word()//' has no sweep named '//sweep
        if (allocated(task)) deallocate (task)
    end subroutine no_sweep_task

    !> Whether deck d asks for this analysis (&scene analyses).
    logical function requested(self, d)
        class(analysis_t), intent(in) :: self
        type(deck_t), intent(in) :: d               !! the deck
        requested = analysis_requested(d, self%word())
    end function requested

    !> The paths of its sweeps' checkpoints for deck NAME in outdir (module checkpoint).
    function checkpoints(self, outdir, name) result(p)
        class(analysis_t), intent(in) :: self
        character(len=*), intent(in) :: outdir      !! output folder
        character(len=*), intent(in) :: name        !! the deck's name
        character(len=len(outdir) + len(name) + WORD_LEN + 10), allocatable :: p(:)
        character(len=WORD_LEN), allocatable :: sw(:)
        integer :: k
        call self%sweeps(sw)
        allocate (p(size(sw)))
        do k = 1, size(sw)
            p(k) = checkpoint_path(outdir, name, trim(sw(k)))
        end do
    end function checkpoints

    !> One more warning line (grown by hand: gfortran 12 loses the text of a constructor
    !! [ws, warning_t(s)]).
    subroutine add_warning(self, s)
        class(analysis_t), intent(inout) :: self
        character(len=*), intent(in) :: s           !! the line (without 'bifilar: warning:')
        type(warning_t), allocatable :: grown(:)
        integer :: j, n
        n = 0
        if (allocated(self%warnings)) n = size(self%warnings)
        allocate (grown(n + 1))
        do j = 1, n
            call move_alloc(self%warnings(j)%s, grown(j)%s)
        end do
        grown(n + 1)%s = s
        call move_alloc(grown, self%warnings)
    end subroutine add_warning

    !> A sweep's warning (a checkpoint that could not be written), when it has one.
    subroutine add_report_warning(self, rep)
        class(analysis_t), intent(inout) :: self
        type(sweep_report_t), intent(in) :: rep     !! the sweep's report
        if (.not. allocated(rep%warning)) return
        if (len(rep%warning) > 0) call self%add_warning(rep%warning)
    end subroutine add_report_warning

    !> ' on N ranks' for a sweep of an MPI run ('' on one rank).
    function ranks_note(rep) result(s)
        type(sweep_report_t), intent(in) :: rep     !! the sweep's report
        character(len=:), allocatable :: s
        s = ''
        if (rep%ranks > 1) s = ' on '//itoa(rep%ranks)//' ranks'
    end function ranks_note

    !> What a sweep took from its checkpoint, or why it could not (--resume).
    function resume_note(rep) result(s)
        type(sweep_report_t), intent(in) :: rep     !! the sweep's report
        character(len=:), allocatable :: s
        s = ''
        if (rep%resumed > 0) s = ', '//itoa(rep%resumed)//' resumed from the checkpoint'
        if (rep%rejected > 0) s = s//', '//itoa(rep%rejected)//' of its points damaged or '// &
            'out of range: computed again'
        if (allocated(rep%note)) then
            if (len(rep%note) > 0) s = s//', '//rep%note//': computed afresh'
        end if
    end function resume_note

end module analysis_base
