!> The house: the module graph and the status table.  The graph of the sources (module_graph.sh
!! --check) keeps its rules: a unit uses only units of its own folder or of folders below,
!! no analysis uses another, only analyses/ and app/ use the deck, at most 8 floors; and the
!! script finds a break of each rule in a small tree made here.  The status table holds every code once, each with an exit
!! status the program can give.
module test_graph
    use testing, only: tester_t, write_text, file_has, run, fresh_dir, first_line
    use status, only: STATUS_TABLE, exit_status_of, status_meaning, STATUS_OK, ERR_DECK, &
        ERR_NUMERIC, ERR_MODEL, ERR_IO, LSODA_ERR_MAX_STEPS, RADAU_ERR_SINGULAR, GEN_ERR_CHART
    implicit none
    private

    public :: run_graph_tests

    character(len=*), parameter :: SCRIPT = 'tests/module_graph.sh'

contains

    !> Suite graph.
    subroutine run_graph_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        associate (unused => exe)
        end associate
        if (t%want('graph: the sources keep the layers, no analysis uses another, 8 floors')) &
            call test_sources(t)
        if (t%want('graph: the check finds a use of a higher folder, an analysis using '// &
                   'another, too many floors')) call test_breaks(t)
        if (t%want('graph: the check finds the deck used below analyses/ and app/')) &
            call test_deck_users(t)
        if (t%want('graph: the status table, one row per code')) call test_status(t)
        if (t%want('graph: no source, test or manual page speaks of issues or commits')) &
            call test_no_history(t)
    end subroutine run_graph_tests

    !> The sources, the tests, doc/ and the README say what the program does, not which
    !! issue or commit brought it: no issue numbers, no commit hashes.
    subroutine test_no_history(t)
        type(tester_t), intent(inout) :: t
        character(len=:), allocatable :: d
        integer :: ex
        d = 'build/test_graph/history'
        call fresh_dir(d)
        ex = run('grep -rnEi "issues? ?#?[0-9]+|issue''s|the iss'//'ue\b|commit [0-9a-f]{7}" '// &
                 'src tests doc README.md Makefile --include=*.f90 --include=*.md '// &
                 '--include=Makefile --include=*.sh --include=*.gp', d)
        call t%check('graph: no source, test or manual page speaks of issues or commits '// &
                     '(first: '//first_line(d//'/stdout')//')', ex == 1)
    end subroutine test_no_history

    subroutine test_sources(t)
        type(tester_t), intent(inout) :: t
        character(len=:), allocatable :: d
        integer :: ex, floors, ios
        character(len=:), allocatable :: last
        d = 'build/test_graph/src'
        call fresh_dir(d)
        ex = run(SCRIPT//' --check src', d)
        call t%check('graph: module_graph.sh --check src exits 0 (no fault)', ex == 0)
        call execute_command_line('tail -n 1 '//d//'/stdout > '//d//'/last')
        last = first_line(d//'/last')
        floors = -1
        read (last, *, iostat=ios) floors
        call t%check('graph: the sources have at most 8 floors ('//last//')', &
                     ios == 0 .and. floors >= 1 .and. floors <= 8)
        call t%check('graph: every folder of src is a layer (no fault line)', &
                     .not. file_has(d//'/stderr', 'module_graph:'))
    end subroutine test_sources

    !> A tree of four files in three folders: each rule broken once.
    subroutine test_breaks(t)
        type(tester_t), intent(inout) :: t
        character(len=:), allocatable :: d, s
        integer :: ex
        d = 'build/test_graph/breaks'
        call fresh_dir(d)
        s = d//'/src'
        call execute_command_line('mkdir -p '//s//'/core '//s//'/analyses '//s//'/runs')
        call write_text(s//'/core/low.f90', 'module low'//NL()//'    use one'//NL()// &
                        'end module low'//NL())
        call write_text(s//'/analyses/one.f90', 'module one'//NL()//'end module one'//NL())
        call write_text(s//'/analyses/two.f90', 'module two'//NL()//'    use one'//NL()// &
                        'end module two'//NL())
        call write_text(s//'/runs/mid.f90', 'module mid'//NL()//'end module mid'//NL())
        ex = run(SCRIPT//' --check '//s, d)
        call t%check('graph breaks: --check exits 1', ex == 1)
        call t%check('graph breaks: a use of a higher folder is named', &
                     file_has(d//'/stderr', 'low (core) uses one of the higher folder analyses'))
        call t%check('graph breaks: an analysis using another is named', &
                     file_has(d//'/stderr', 'two uses one: an analysis uses another analysis'))
        ex = run(SCRIPT//' '//s, d)
        call t%check('graph breaks: without --check the graph is printed, exit 0', &
                     all([ex == 0, file_has(d//'/stdout', 'floors, 4 units')]))
        ! nine floors in one folder: a chain m1 <- m2 <- ... <- m9
        call execute_command_line('rm -rf '//s//' && mkdir -p '//s//'/core && for i in 1 2 '// &
            '3 4 5 6 7 8 9; do { echo "module m$i"; [ $i -gt 1 ] && echo "    use m$((i-1))"; '// &
            'echo "end module m$i"; } > '//s//'/core/m$i.f90; done')
        ex = run(SCRIPT//' --check '//s, d)
        call t%check('graph breaks: 9 floors fail the check, named', all([ex == 1, &
                     file_has(d//'/stderr', 'the graph has 9 floors; allowed: at most 8')]))
    end subroutine test_breaks

    !> A tree where the deck lies in io/ (below measure/, so no use of it breaks the layers):
    !! a unit of measure/ that uses it is named; the analysis and the program that use it,
    !! and the deck's own folder, are not.
    subroutine test_deck_users(t)
        type(tester_t), intent(inout) :: t
        character(len=:), allocatable :: d, s
        integer :: ex
        d = 'build/test_graph/deck_users'
        call fresh_dir(d)
        s = d//'/src'
        call execute_command_line('mkdir -p '//s//'/io '//s//'/measure '//s//'/analyses '// &
                                  s//'/app')
        call write_text(s//'/io/deck.f90', 'module deck'//NL()//'end module deck'//NL())
        call write_text(s//'/measure/fit.f90', 'module fit'//NL()//'    use deck, only: x'// &
                        NL()//'end module fit'//NL())
        call write_text(s//'/analyses/one.f90', 'module one'//NL()//'    use deck'//NL()// &
                        '    use fit'//NL()//'end module one'//NL())
        call write_text(s//'/app/main.f90', 'program main'//NL()//'    use deck'//NL()// &
                        '    use one'//NL()//'end program main'//NL())
        ex = run(SCRIPT//' --check '//s, d)
        call t%check('graph deck: --check exits 1', ex == 1)
        call t%check('graph deck: a unit of measure/ using the deck is named', &
                     file_has(d//'/stderr', 'fit (measure) uses deck: only analyses/ and app/ '// &
                     'use the deck'))
        call t%check('graph deck: the analysis using it is not named', &
                     .not. file_has(d//'/stderr', 'one (analyses) uses deck'))
        call t%check('graph deck: the program using it is not named', &
                     .not. file_has(d//'/stderr', 'main (app) uses deck'))
        call t%check('graph deck: no other fault (the layers hold)', .not. &
                     file_has(d//'/stderr', 'higher folder'))
        ! without the faulty use, the same tree passes
        call write_text(s//'/measure/fit.f90', 'module fit'//NL()//'end module fit'//NL())
        ex = run(SCRIPT//' --check '//s, d)
        call t%check('graph deck: without that use the check passes', ex == 0)
    end subroutine test_deck_users

    subroutine test_status(t)
        type(tester_t), intent(inout) :: t
        integer :: i, j
        logical :: unique, ranged
        unique = .true.
        ranged = .true.
        do i = 1, size(STATUS_TABLE)
            do j = i + 1, size(STATUS_TABLE)
                if (STATUS_TABLE(i)%code == STATUS_TABLE(j)%code) unique = .false.
            end do
            if (STATUS_TABLE(i)%code /= STATUS_OK) ranged = ranged .and. &
                STATUS_TABLE(i)%exit_status >= 2 .and. STATUS_TABLE(i)%exit_status <= 5
        end do
        call t%check('status: every code of the table once', unique)
        call t%check('status: every error''s exit status is 2 .. 5', ranged)
        call t%check('status: exit statuses of the five kinds', all([exit_status_of(STATUS_OK), &
            exit_status_of(ERR_DECK), exit_status_of(ERR_NUMERIC), exit_status_of(ERR_MODEL), &
            exit_status_of(ERR_IO)] == [0, 2, 3, 4, 5]))
        call t%check('status: the integrators'' and the chart''s codes are numerical failures', &
            all([exit_status_of(LSODA_ERR_MAX_STEPS), exit_status_of(RADAU_ERR_SINGULAR), &
                 exit_status_of(GEN_ERR_CHART), exit_status_of(999)] == 3))
        call t%check('status: the error kinds', status_meaning(ERR_DECK) == 'bad input' .and. &
            status_meaning(ERR_MODEL) == 'model no longer valid' .and. &
            status_meaning(ERR_IO) == 'cannot write output' .and. &
            status_meaning(LSODA_ERR_MAX_STEPS) == 'numerical failure')
    end subroutine test_status

    pure function NL() result(c)
        character(len=1) :: c
        c = achar(10)
    end function NL

end module test_graph
