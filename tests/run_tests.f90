!> The test runner: `run_tests [BIFILAR_EXE [FILTER]]` runs the suites of the table (module
!! suites) in turn, or those FILTER selects, and ends with the line "N passed, N failed";
!! exit status 1 when a check failed, 2 when FILTER selects nothing or the arguments are
!! wrong.  `run_tests --list` prints the suites, `run_tests --help` the usage.
program run_tests
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use testing, only: tester_t
    use suites, only: suite_t, suite_table, suite_names, NAME_LEN
    implicit none

    interface
        !> The C library's exit(3): ends the program with this status, without the run-time
        !! library's STOP line.
        subroutine c_exit(status) bind(c, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
    end interface

    character(len=*), parameter :: NL = new_line('a')
    character(len=*), parameter :: USAGE = &
        'usage: run_tests [BIFILAR_EXE [FILTER]]   run the suites (default bin/bifilar, all)'// &
        NL//'       run_tests --list                    the suites: name and description'// &
        NL//'       run_tests --help                    this text'//NL// &
        NL//'FILTER selects the suites whose name contains it, and in the other suites the'// &
        NL//'checks whose label (printed as "== LABEL") contains it; a FILTER that selects'// &
        NL//'nothing is an error.  The last line is "N passed, N failed"; the exit status is'// &
        NL//'0 when nothing failed, 1 when a check failed, 2 when nothing was selected or the'// &
        NL//'arguments are wrong.'
    type(suite_t), allocatable :: table(:)
    type(tester_t) :: t
    character(len=4096) :: arg
    character(len=:), allocatable :: exe, filter
    integer :: k, npos, nselected, times_unit, ios
    integer(kind=8) :: c0, c1, rate
    character(len=4096) :: times_file
    logical :: ok, timing

    allocate (table, source=suite_table())
    exe = 'bin/bifilar'
    filter = ''
    npos = 0
    do k = 1, command_argument_count()
        call get_command_argument(k, arg)
        select case (trim(arg))
        case ('--help', '-h')
            write (*, '(a)') USAGE
            stop
        case ('--list')
            call list_suites()
            stop
        case default
            if (index(arg, '--') == 1) call usage_error('unknown option '//trim(arg))
            npos = npos + 1
            if (npos == 1) exe = trim(arg)
            if (npos == 2) filter = trim(arg)
            if (npos > 2) call usage_error('more than two arguments (quote a FILTER with '// &
                                           'blanks)')
        end select
    end do

    ! A suite whose name contains the filter runs whole; every other suite runs the parts
    ! whose label contains it (tester_t%want counts them).
    ! RUN_TESTS_TIMES=FILE: each suite's wall time (s) appended to FILE, to find the slow ones
    ! (never asserted: timing is measured by make bench, not by the tests).
    timing = .false.
    times_unit = 0
    call get_environment_variable('RUN_TESTS_TIMES', times_file, status=ios)
    if (ios == 0 .and. len_trim(times_file) > 0) then
        open (newunit=times_unit, file=trim(times_file), position='append', action='write', &
              iostat=ios)
        timing = ios == 0
    end if
    nselected = 0
    do k = 1, size(table)
        if (len(filter) == 0 .or. index(trim(table(k)%name), filter) > 0) then
            t%only = ''
            nselected = nselected + 1
        else
            t%only = filter
        end if
        call system_clock(c0, rate)
        call table(k)%run(t, exe)
        call system_clock(c1)
        if (timing) write (times_unit, '(a,1x,f9.2)') trim(table(k)%name), &
            real(c1 - c0, kind(1.0d0))/real(rate, kind(1.0d0))
    end do
    if (timing) close (times_unit)
    ok = t%summary()
    if (len(filter) > 0 .and. nselected == 0 .and. t%wanted == 0) then
        flush (output_unit)
        write (error_unit, '(a)') 'run_tests: '''//filter//''' selects no suite and no '// &
            'check (no suite name, no label contains it); the suites: '// &
            suite_names(table, ', ')
        flush (error_unit)
        call c_exit(2_c_int)
    end if
    if (.not. ok) error stop 1

contains

    !> The suites, one per line: name and description.
    subroutine list_suites()
        integer :: i, w
        w = 0
        do i = 1, size(table)
            w = max(w, len_trim(table(i)%name))
        end do
        w = min(w, NAME_LEN)
        do i = 1, size(table)
            write (*, '(a)') table(i)%name(1:w)//'  '//trim(table(i)%about)
        end do
    end subroutine list_suites

    !> Bad arguments: what is wrong and the usage on stderr, exit status 2.
    subroutine usage_error(what)
        character(len=*), intent(in) :: what
        write (error_unit, '(a)') 'run_tests: '//what
        write (error_unit, '(a)') USAGE
        flush (error_unit)
        call c_exit(2_c_int)
    end subroutine usage_error

end program run_tests
