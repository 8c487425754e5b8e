!> One deck from start to end, as the program runs it: read and validate the deck, check
!! the preconditions of every analysis it asks for before any computing, run the analyses
!! with all their files in one out_files_t, and commit those files together at the end, or
!! remove every one of them when anything fails.  The main program only reads the command
!! line, calls run_deck for each deck and prints what comes back.
!!
!! The analyses are those of the registry (analysis_registry, in submodule registry:
!! src/app/registry.f90), each an analysis_t (module analysis_base) that owns its
!! preconditions, its run, its part of the summary line, its files, its checkpoints and its
!! sweeps' tasks.  The driver keeps the order: every precondition in the registry's order,
!! then the runs (those whose runs_first is true first, then the others, each group in the
!! registry's order), the summary line's parts in the registry's order; and the commit or
!! discard of the files, the warnings, the stage names of module signals.
!!
!! Signals: the line a signal prints names the deck and the analysis running (module
!! signals); the deck's files are renamed into place with signals deferred, so that a signal
!! never leaves part of a set (the main program acts on it once the deck's line is out).
!!
!! In an MPI run (bin/bifilar_mpi) rank 0 runs the decks; the other ranks only compute
!! points of sweeps (serve_sweeps): for each sweep rank 0 announces, they read the deck,
!! build the same task (the analysis whose sweeps name it gives it) and take part
!! (module sweep_engine).
module driver
    use, intrinsic :: iso_fortran_env, only: error_unit
    use status, only: status_t, STATUS_OK, ERR_DECK, exit_status_of, status_meaning
    use deck, only: deck_t, read_deck, read_deck_text
    use output_io, only: out_files_t, remove_file, path_fits
    use signals, only: signals_deck, signals_stage, signals_defer
    use sweep_engine, only: sweep_options_t, sweep_job_t, sweep_task_t, sweep_next_job, &
        sweep_serve
    use analysis_base, only: analysis_slot_t, warning_t, WORD_LEN
    implicit none
    private

    public :: run_deck, exit_status, error_line, serve_sweeps, analysis_registry

    !> The program's version (bifilar --version).
    character(len=*), parameter, public :: BIFILAR_VERSION = '1.1'

    interface
        !> Every analysis of the program, one fresh object each, in the order of the summary
        !! line (submodule registry).
        module subroutine analysis_registry(reg)
            type(analysis_slot_t), allocatable, intent(out) :: reg(:)
        end subroutine analysis_registry
    end interface

contains

    !> Run the deck at `path` into the folder `outdir` (which exists).  On success `line`
    !! is the deck's one summary line and stat is OK; on failure stat carries the error
    !! (its message without the deck's name: error_line adds it) and no file of the run is
    !! left in outdir.  The analyses whose runs_first is true (the sweeps chart and design)
    !! run first, before any file of the run is staged (the chart's before the design's);
    !! identify's and tensor's Monte Carlo are sweeps too, in their turn.  Their
    !! checkpoints (each analysis's checkpoints(outdir, name)) are removed once the run's
    !! files are committed, and kept when the run fails after them (--resume reuses them).
    !! On a commit the files of the deck's analyses (their owned_extensions) that this run
    !! did not write are removed.
    !! Warnings (a suspicious result that stands, a checkpoint that could not be written:
    !! one line each) go to stderr as "bifilar: warning: DECK: ...", or to `warnings` when
    !! given; they come once the deck's files are committed.
    !! With signals deferred when it returns (module signals): the caller prints the deck's
    !! line, then releases them.
    subroutine run_deck(path, outdir, line, stat, options, warnings)
        character(len=*), intent(in) :: path        !! deck file
        character(len=*), intent(in) :: outdir      !! output folder
        character(len=:), allocatable, intent(out) :: line   !! summary (on success)
        type(status_t), intent(out) :: stat         !! the first failure
        type(sweep_options_t), intent(in), optional :: options   !! --resume, --checkpoint
        !> the run's warnings, returned instead of written to stderr
        type(warning_t), allocatable, intent(out), optional :: warnings(:)
        type(deck_t) :: d
        type(out_files_t) :: files
        type(analysis_slot_t), allocatable :: reg(:)
        logical, allocatable :: asked(:)
        integer, allocatable :: order(:)
        type(warning_t), allocatable :: ws(:)
        integer :: i, j, k

        line = ''
        call signals_deck(path)
        call read_deck(path, d, stat)
        if (stat%code /= STATUS_OK) return
        call analysis_registry(reg)
        ! the output folder can take the deck's files (before any computing)
        call path_fits(outdir, d%name//longest_suffix(reg), stat)
        if (stat%code /= STATUS_OK) return

        ! every analysis's preconditions before any computing
        allocate (asked(size(reg)))
        do k = 1, size(reg)
            asked(k) = reg(k)%a%requested(d)
        end do
        do k = 1, size(reg)
            if (.not. asked(k)) cycle
            call reg(k)%a%ready(d, stat)
            if (stat%code /= STATUS_OK) return
        end do

        run: block
            order = run_order(reg)
            do j = 1, size(order)
                k = order(j)
                if (.not. asked(k)) cycle
                call signals_stage(reg(k)%a%word())
                call reg(k)%a%run(d, outdir, files, stat, options)
                if (stat%code /= STATUS_OK) exit run
            end do
            line = d%name//':'
            do k = 1, size(reg)
                if (asked(k)) line = line//reg(k)%a%summary(d)
            end do
            ! renamed into place together, and the line printed, before a signal is acted on
            call signals_defer()
            call files%commit(stat, stale_files())  ! on failure it removes them all
            if (stat%code == STATUS_OK) then
                line = line(1:len(line) - 1)
                allocate (ws(0))
                do j = 1, size(order)
                    k = order(j)
                    if (.not. asked(k)) cycle
                    call remove_files(reg(k)%a%checkpoints(outdir, d%name))
                    if (.not. allocated(reg(k)%a%warnings)) cycle
                    do i = 1, size(reg(k)%a%warnings)
                        call add_text(reg(k)%a%warnings(i)%s)
                    end do
                end do
                if (present(warnings)) then
                    call move_alloc(ws, warnings)
                else
                    do i = 1, size(ws)
                        call warn(path, ws(i)%s)
                    end do
                end if
            end if
            return
        end block run
        call files%discard()                    ! a failed analysis: remove every file

    contains

        !> One more warning (grown by hand: gfortran 12 loses the text of a constructor
        !! [ws, warning_t(s)] here).
        subroutine add_text(s)
            character(len=*), intent(in) :: s
            type(warning_t), allocatable :: grown(:)
            integer :: m
            allocate (grown(size(ws) + 1))
            do m = 1, size(ws)
                call move_alloc(ws(m)%s, grown(m)%s)
            end do
            grown(size(ws) + 1)%s = s
            call move_alloc(grown, ws)
        end subroutine add_text

        !> OUTDIR/NAME.EXT of every file the deck's analyses may write (owned_extensions).
        function stale_files() result(p)
            character(len=len(outdir) + len(d%name) + WORD_LEN + 1), allocatable :: p(:)
            character(len=WORD_LEN), allocatable :: ext(:)
            integer :: i, e
            allocate (p(0))
            do i = 1, size(reg)
                if (.not. asked(i)) cycle
                call reg(i)%a%owned_extensions(ext)
                do e = 1, size(ext)
                    p = [character(len=len(p)) :: p, outdir//'/'//d%name//trim(ext(e))]
                end do
            end do
        end function stale_files

    end subroutine run_deck

    !> Remove each of the files `paths` (trailing blanks dropped) that exists.
    subroutine remove_files(paths)
        character(len=*), intent(in) :: paths(:)        !! the files
        integer :: k
        do k = 1, size(paths)
            call remove_file(trim(paths(k)))
        end do
    end subroutine remove_files

    !> The order of the runs: the registry's indices of the analyses whose runs_first is
    !! true, then those of the others, each in the registry's order.
    function run_order(reg) result(order)
        type(analysis_slot_t), intent(in) :: reg(:)     !! the registry
        integer, allocatable :: order(:)
        integer :: k
        allocate (order(0))
        do k = 1, size(reg)
            if (reg(k)%a%runs_first()) order = [order, k]
        end do
        do k = 1, size(reg)
            if (.not. reg(k)%a%runs_first()) order = [order, k]
        end do
    end function run_order

    !> The longest name an analysis of the registry makes in the output folder after the
    !! deck's name, before the temporary suffix: a file it owns (.EXT) or a checkpoint of
    !! its sweeps (.SWEEP.partial); the first of the longest.
    function longest_suffix(reg) result(s)
        type(analysis_slot_t), intent(in) :: reg(:)     !! the registry
        character(len=:), allocatable :: s
        character(len=WORD_LEN), allocatable :: w(:)
        integer :: k, j
        s = ''
        do k = 1, size(reg)
            call reg(k)%a%owned_extensions(w)
            do j = 1, size(w)
                if (len_trim(w(j)) > len(s)) s = trim(w(j))
            end do
            call reg(k)%a%sweeps(w)
            do j = 1, size(w)
                if (len_trim(w(j)) + 9 > len(s)) s = '.'//trim(w(j))//'.partial'
            end do
        end do
    end function longest_suffix

    !> A warning: one line on stderr naming the deck (the run goes on, exit 0).
    subroutine warn(deck_path, msg)
        character(len=*), intent(in) :: deck_path   !! the deck as given
        character(len=*), intent(in) :: msg         !! what is suspicious, what to check
        write (error_unit, '(a)') 'bifilar: warning: '//deck_path//': '//msg
        flush (error_unit)
    end subroutine warn

    !> The other ranks of an MPI run: for each sweep rank 0 announces, read its deck, build
    !! its task (the analysis of the registry whose sweeps name it) and compute points,
    !! until rank 0 ends the program.
    subroutine serve_sweeps()
        type(sweep_job_t) :: job
        type(deck_t) :: d
        type(status_t) :: st
        class(sweep_task_t), allocatable :: task
        type(analysis_slot_t), allocatable :: reg(:)
        logical :: quit
        integer :: k
        call analysis_registry(reg)
        do
            call sweep_next_job(job, quit)
            if (quit) return
            if (len(job%deck_text) > 0) then
                call read_deck_text(job%deck_path, job%deck_text, d, st)
            else
                call read_deck(job%deck_path, d, st)
            end if
            if (st%code == STATUS_OK) then
                k = sweep_owner(reg, job%analysis)
                if (k > 0) then
                    call reg(k)%a%sweep_task(job%analysis, d, job%payload, task, st)
                else
                    st%code = ERR_DECK
                    st%msg = 'no sweep named '//job%analysis//' in this executable'
                end if
            else
                st%msg = job%deck_path//': '//st%msg
            end if
            if (allocated(task) .and. st%code == STATUS_OK) then
                call sweep_serve(job, st, task)
            else
                call sweep_serve(job, st)
            end if
            if (allocated(task)) deallocate (task)
        end do
    end subroutine serve_sweeps

    !> The index in the registry of the analysis whose sweeps hold `sweep` (0: none).
    integer function sweep_owner(reg, sweep)
        type(analysis_slot_t), intent(in) :: reg(:)     !! the registry
        character(len=*), intent(in) :: sweep           !! a sweep's name, e.g. 'chart'
        character(len=WORD_LEN), allocatable :: w(:)
        integer :: k
        do sweep_owner = 1, size(reg)
            call reg(sweep_owner)%a%sweeps(w)
            do k = 1, size(w)
                if (trim(w(k)) == sweep) return
            end do
        end do
        sweep_owner = 0
    end function sweep_owner

    !> The exit status for a status code (status's STATUS_TABLE): 2 bad deck, 3 numerical
    !! failure, 4 the model no longer holds, 5 output cannot be written.
    pure integer function exit_status(code)
        integer, intent(in) :: code                 !! status_t%code
        exit_status = exit_status_of(code)
    end function exit_status

    !> The one line printed for a failed deck: 'bifilar: error (KIND): DECK: MESSAGE', line
    !! breaks in the message turned into blanks.
    function error_line(deck_path, stat) result(s)
        character(len=*), intent(in) :: deck_path   !! the deck as given ('' for none)
        type(status_t), intent(in) :: stat          !! the failure
        character(len=:), allocatable :: s
        character(len=:), allocatable :: kind, msg
        integer :: i
        kind = status_meaning(stat%code)
        msg = '(no message)'
        if (allocated(stat%msg)) msg = stat%msg
        do i = 1, len(msg)
            if (iachar(msg(i:i)) < 32) msg(i:i) = ' '
        end do
        s = 'bifilar: error ('//kind//'): '
        if (len(deck_path) > 0) s = s//deck_path//': '
        s = s//msg
    end function error_line

end module driver
