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
    integer :: k, npos, nselected
    logical :: ok

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
    nselected = 0
    do k = 1, size(table)
        if (len(filter) == 0 .or. index(trim(table(k)%name), filter) > 0) then
            t%only = ''
            nselected = nselected + 1
        else
            t%only = filter
        end if
        call table(k)%run(t, exe)
    end do
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
