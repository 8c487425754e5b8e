!> bifilar: dynamics of the bifilar pendulum (Kane & Tseng 1966), driven by namelist decks.
!!
!! Usage:  bifilar DECK.nml [DECK.nml ...] [--out DIR] [--resume] [--checkpoint SECONDS]
!!         mpirun -np N bifilar_mpi DECK.nml ... (the MPI build: sweeps over N ranks)
!!         bifilar --report [DIR]   (DIR/report.md from the paper scenes' output in DIR)
!!         bifilar --help | --version
!! Runs each deck in turn (module driver) and writes DIR/NAME.* (DIR defaults to `output`
!! and is created when missing); one summary line per deck on standard output, one error
!! line per failed deck on standard error.  Exit status: the worst (largest) of the decks':
!! 0 success, 1 usage, 2 bad deck, 3 numerical failure, 4 the model no longer holds (e.g. a
!! cable goes slack), 5 output cannot be written.
!!
!! In the MPI build every rank starts here; rank 0 goes on as the serial program does, the
!! others serve the sweeps rank 0 hands out (driver's serve_sweeps) until it ends the run.
!!
!! The program ends through C's exit() after flushing its output, so that nothing but its
!! own lines reaches the terminal (gfortran's `error stop` adds "ERROR STOP n" and notes on
!! floating-point flags).
!!
!! SIGINT, SIGTERM and SIGHUP (module signals) stop the run at any moment with one line,
!! no temporary file left and exit status 128 + the signal; a deck's files are renamed
!! into place and its line printed before a signal is acted on, and once the last deck's
!! line is out signals are ignored.  The other ranks of an MPI run end quietly.
program bifilar
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    use kinds, only: dp
    use status, only: status_t, STATUS_OK, EXIT_OK, EXIT_USAGE
    use text, only: itoa
    use output_io, only: make_dir
    use signals, only: signals_install, signals_worker, signals_deck, signals_stage, &
        signals_release, signals_ignore
    use paper_claims, only: write_report
    use driver, only: run_deck, exit_status, error_line, BIFILAR_VERSION, serve_sweeps
    use sweep_engine, only: sweep_start, sweep_finish, sweep_is_master, sweep_library, &
        sweep_options_t
    implicit none
    interface
        !> C library exit(3): ends the process with `status`, running the exit handlers
        !! (the Fortran run-time library closes its units there).
        subroutine c_exit(status) bind(C, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
    end interface
    character(len=*), parameter :: USAGE_LINE = &
        'usage: bifilar DECK.nml [DECK.nml ...] [--out DIR] [--resume] [--checkpoint '// &
        'SECONDS] | bifilar --report [DIR] | bifilar --help | bifilar --version'
    type :: arg_t
        character(len=:), allocatable :: s
    end type arg_t
    type(arg_t), allocatable :: decks(:)
    type(arg_t) :: outdir, arg, line, report_dir  ! strings in a type: gfortran 12 warns on
                                                   ! deferred-length ones of a main program
    type(status_t) :: stat
    type(sweep_options_t) :: sweep_opts
    integer :: i, nargs, ndecks, worst, ios
    logical :: report, options_done, out_given

    call sweep_start(stat)
    if (.not. sweep_is_master()) then
        call signals_worker()
        if (stat%code == STATUS_OK) call serve_sweeps()
        call finish(EXIT_OK)
    end if
    call signals_install()
    if (stat%code /= STATUS_OK) then
        call say(error_unit, error_line('', stat))
        call finish(exit_status(stat%code))
    end if
    nargs = command_argument_count()
    outdir%s = 'output'
    out_given = .false.
    report = .false.
    report_dir%s = 'output'
    options_done = .false.
    allocate (decks(nargs))
    ndecks = 0
    i = 1
    do while (i <= nargs)
        arg%s = argument(i)
        i = i + 1
        if (options_done .or. len(arg%s) == 0) then
            if (len(arg%s) == 0) call usage('an empty deck name')
            ndecks = ndecks + 1
            decks(ndecks)%s = arg%s
            cycle
        end if
        if (arg%s == '--') then
            options_done = .true.
        else if (arg%s == '--help' .or. arg%s == '-h') then
            call help()
        else if (arg%s == '--version' .or. arg%s == '-V') then
            if (sweep_library() == 'none (serial build)') then
                write (output_unit, '(a)') 'bifilar '//BIFILAR_VERSION
            else
                write (output_unit, '(a)') 'bifilar '//BIFILAR_VERSION//' (MPI: '// &
                    sweep_library()//')'
            end if
            call finish(EXIT_OK)
        else if (arg%s == '--resume') then
            sweep_opts%resume = .true.
        else if (arg%s == '--checkpoint' .or. index(arg%s, '--checkpoint=') == 1) then
            arg%s = option_value('--checkpoint', 'a number of seconds')
            read (arg%s, *, iostat=ios) sweep_opts%checkpoint_seconds
            if (ios /= 0 .or. verify(trim(arg%s), '0123456789.eE+-') /= 0 .or. &
                len_trim(arg%s) == 0) call usage('--checkpoint needs a number of seconds '// &
                '(got '''//arg%s//''')')
            if (.not. (sweep_opts%checkpoint_seconds >= 0.0_dp .and. &
                       sweep_opts%checkpoint_seconds <= 1.0e6_dp)) &
                call usage('--checkpoint SECONDS must be 0 ... 1e6 (got '//arg%s//')')
        else if (arg%s == '--report') then
            report = .true.
            if (i <= nargs) then
                arg%s = argument(i)
                if (len(arg%s) > 0) then
                    if (arg%s(1:1) /= '-') then
                        report_dir%s = arg%s
                        i = i + 1
                    end if
                end if
            end if
        else if (arg%s == '--out' .or. index(arg%s, '--out=') == 1) then
            outdir%s = option_value('--out', 'a folder name')
            if (len(outdir%s) == 0) call usage('--out needs a folder name (got an empty one)')
            out_given = .true.
        else if (arg%s(1:1) == '-' .and. len(arg%s) > 1) then
            call usage('unknown option '//arg%s)
        else
            ndecks = ndecks + 1
            decks(ndecks)%s = arg%s
        end if
    end do

    if (report) then
        if (ndecks > 0 .or. out_given) call usage('--report takes no decks and no --out')
        call signals_stage('report')
        call write_report(report_dir%s, stat)
        if (stat%code /= STATUS_OK) then
            call say(error_unit, error_line('', stat))
            call finish(exit_status(stat%code))
        end if
        call say(output_unit, 'wrote '//report_dir%s//'/report.md')
        call finish(EXIT_OK)
    end if
    if (ndecks == 0) call usage('no deck given')

    ! the output folder, before any computing
    call make_dir(outdir%s, stat)
    if (stat%code /= STATUS_OK) then
        ! the folder serves every deck: the line names the first (and how many more)
        stat%msg = '--out: '//stat%msg
        if (ndecks > 1) stat%msg = stat%msg//' (for this deck and '//itoa(ndecks - 1)// &
            ' more; none was run)'
        call say(error_unit, error_line(decks(1)%s, stat))
        call finish(exit_status(stat%code))
    end if

    worst = EXIT_OK
    do i = 1, ndecks
        call run_deck(decks(i)%s, outdir%s, line%s, stat, sweep_opts)
        if (stat%code == STATUS_OK) then
            call say(output_unit, line%s)
        else
            call say(error_unit, error_line(decks(i)%s, stat))
        end if
        flush (output_unit)
        flush (error_unit)
        worst = max(worst, exit_status(stat%code))
        ! a signal that came while the deck's files were renamed into place: the next deck
        ! is not run (or, after the last one, the run is complete and it is ignored)
        if (i == ndecks) then
            call signals_ignore()
        else
            call signals_deck(decks(i + 1)%s)
        end if
        call signals_release()
    end do
    call finish(worst)

contains

    !> Command argument i, of any length.
    function argument(k) result(a)
        integer, intent(in) :: k
        character(len=:), allocatable :: a
        integer :: n
        call get_command_argument(k, length=n)
        allocate (character(len=n) :: a)
        if (n > 0) call get_command_argument(k, a)
    end function argument

    !> The value of option `name` in arg%s: `name VALUE` (the next argument) or
    !! `name=VALUE`; a usage error when the value is missing.
    function option_value(name, what) result(v)
        character(len=*), intent(in) :: name        !! e.g. '--out'
        character(len=*), intent(in) :: what        !! what the value is, for the message
        character(len=:), allocatable :: v
        if (arg%s == name) then
            if (i > nargs) call usage(name//' needs '//what)
            v = argument(i)
            i = i + 1
        else
            v = arg%s(len(name) + 2:)
        end if
    end function option_value

    !> One line on a unit.
    subroutine say(unit, text)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        write (unit, '(a)') text
    end subroutine say

    !> A usage error: one line naming it and the usage, exit status 1.
    subroutine usage(msg)
        character(len=*), intent(in) :: msg
        call say(error_unit, 'bifilar: '//msg//'; '//USAGE_LINE)
        call finish(EXIT_USAGE)
    end subroutine usage

    !> --help: what the program does, its arguments and exit statuses; exit status 0.
    subroutine help()
        call say(output_unit, 'bifilar '//BIFILAR_VERSION//': dynamics of the bifilar '// &
                 'pendulum (Kane & Tseng 1966)')
        call say(output_unit, USAGE_LINE)
        call say(output_unit, '  DECK.nml ...    namelist decks, run in turn; DIR/NAME.dat, '// &
                 '.summary, ... per deck (NAME: the file name without .nml)')
        call say(output_unit, '  --out DIR       output folder (default output), created '// &
                 'when missing')
        call say(output_unit, '  --resume        continue the sweeps (chart, design, '// &
                 'identify''s Monte Carlo) from their checkpoints DIR/NAME.*.partial when of '// &
                 'the same deck and executable')
        call say(output_unit, '  --checkpoint S  write a sweep''s checkpoint at most every S '// &
                 'seconds (default 5; at most 5 % of the time)')
        call say(output_unit, '  --report [DIR]  DIR/report.md from the paper scenes'' '// &
                 'output in DIR (default output)')
        call say(output_unit, '  --help, --version')
        call say(output_unit, 'One summary line per deck on standard output, one error line '// &
                 'per failed deck on standard error; a failed deck leaves no file.')
        call say(output_unit, 'Exit status (the largest over the decks): 0 success, 1 usage, '// &
                 '2 bad deck, 3 numerical failure, 4 the model no longer holds, 5 output '// &
                 'cannot be written.')
        call finish(EXIT_OK)
    end subroutine help

    !> End the program with `status`, printing nothing more (the main program's strings are
    !! freed first: nothing frees them at exit, and valgrind counts them as lost).
    subroutine finish(status)
        integer, intent(in) :: status
        call signals_ignore()                   ! everything is said
        if (allocated(decks)) deallocate (decks)
        if (allocated(outdir%s)) deallocate (outdir%s)
        if (allocated(arg%s)) deallocate (arg%s)
        if (allocated(line%s)) deallocate (line%s)
        if (allocated(report_dir%s)) deallocate (report_dir%s)
        if (allocated(stat%msg)) deallocate (stat%msg)
        flush (output_unit)
        flush (error_unit)
        call sweep_finish()
        call c_exit(int(status, c_int))
    end subroutine finish

end program bifilar
