!> The house: the module graph, the registry of analyses and the status table.  The graph
!! of the sources (module_graph.sh --check) keeps its rules: a unit uses only units of its
!! own folder or of folders below, no analysis uses another (the shared base analysis_base
!! is not an analysis), only analyses/ and app/ use the deck, at most 8 floors; and the
!! script finds a break of each rule in a small tree made here.  The registry (driver's
!! analysis_registry) holds every word of &scene analyses once and no other, and no file or
!! sweep belongs to two analyses.  The status table holds every code once, each with an
!! exit status the program can give.
module test_graph
    use testing, only: tester_t, write_text, file_has, run, fresh_dir, first_line, shell_count
    use status, only: STATUS_TABLE, exit_status_of, status_meaning, STATUS_OK, ERR_DECK, &
        ERR_NUMERIC, ERR_MODEL, ERR_IO, LSODA_ERR_MAX_STEPS, RADAU_ERR_SINGULAR, GEN_ERR_CHART
    use text, only: next_word
    use unused_arg, only: unused
    use analysis_groups, only: ANALYSES_ALLOWED
    use analysis_base, only: analysis_slot_t, WORD_LEN
    use driver, only: analysis_registry
    implicit none
    private

    public :: run_graph_tests

    character(len=*), parameter :: SCRIPT = 'tests/module_graph.sh'

contains

    !> Suite graph.
    subroutine run_graph_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        call unused(exe)
        if (t%want('graph: the sources keep the layers, no analysis uses another, 8 floors')) &
            call test_sources(t)
        if (t%want('graph: the check finds a use of a higher folder, an analysis using '// &
                   'another, too many floors')) call test_breaks(t)
        if (t%want('graph: the check finds the deck used below analyses/ and app/')) &
            call test_deck_users(t)
        if (t%want('graph: every analysis may use the shared base, the base uses none')) &
            call test_shared_base(t)
        if (t%want('graph: the registry holds every word of &scene analyses once, no file '// &
                   'or sweep in two analyses')) call test_registry(t)
        if (t%want('graph: module state only where src/README.md says, one idiom for an '// &
                   'unused argument')) call test_state_and_idiom(t)
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

    !> A tree of analyses/ with the shared base: the analyses that use it pass; the base that
    !! uses an analysis is named.
    subroutine test_shared_base(t)
        type(tester_t), intent(inout) :: t
        character(len=:), allocatable :: d, s
        integer :: ex
        d = 'build/test_graph/shared_base'
        call fresh_dir(d)
        s = d//'/src'
        call execute_command_line('mkdir -p '//s//'/analyses')
        call write_text(s//'/analyses/analysis_base.f90', 'module analysis_base'//NL()// &
                        'end module analysis_base'//NL())
        call write_text(s//'/analyses/one.f90', 'module one'//NL()//'    use analysis_base'// &
                        NL()//'end module one'//NL())
        call write_text(s//'/analyses/two.f90', 'module two'//NL()//'    use analysis_base'// &
                        NL()//'end module two'//NL())
        ex = run(SCRIPT//' --check '//s, d)
        call t%check('graph shared base: analyses that use analysis_base pass', ex == 0)
        call write_text(s//'/analyses/analysis_base.f90', 'module analysis_base'//NL()// &
                        '    use one'//NL()//'end module analysis_base'//NL())
        call write_text(s//'/analyses/one.f90', 'module one'//NL()//'end module one'//NL())
        ex = run(SCRIPT//' --check '//s, d)
        call t%check('graph shared base: the base using an analysis is named', all([ex == 1, &
                     file_has(d//'/stderr', 'analysis_base uses one: an analysis uses another '// &
                     'analysis')]))
    end subroutine test_shared_base

    !> The registry against &scene analyses: each word of ANALYSES_ALLOWED has one analysis
    !! and each analysis one word of it; each file extension and each sweep belongs to one
    !! analysis; an analysis that runs first has a sweep (what puts it first).
    subroutine test_registry(t)
        type(tester_t), intent(inout) :: t
        type(analysis_slot_t), allocatable :: reg(:)
        character(len=WORD_LEN), allocatable :: words(:), exts(:), sweeps(:), w(:)
        character(len=WORD_LEN) :: missing, stray, twice
        integer :: k, j, i1, i2
        logical :: first_ok
        call analysis_registry(reg)
        allocate (words(0), exts(0), sweeps(0))
        first_ok = .true.
        do k = 1, size(reg)
            words = [character(len=WORD_LEN) :: words, reg(k)%a%word()]
            call reg(k)%a%owned_extensions(w)
            exts = [character(len=WORD_LEN) :: exts, w]
            call reg(k)%a%sweeps(w)
            sweeps = [character(len=WORD_LEN) :: sweeps, w]
            if (reg(k)%a%runs_first() .and. size(w) == 0) first_ok = .false.
        end do
        ! every allowed word in the registry once
        missing = ''
        i2 = 0
        do
            call next_word(ANALYSES_ALLOWED, i2, i1)
            if (i1 == 0) exit
            if (count(words == ANALYSES_ALLOWED(i1:i2)) /= 1) missing = ANALYSES_ALLOWED(i1:i2)
        end do
        call t%check('registry: every word of ANALYSES_ALLOWED has one analysis (not: '// &
                     trim(missing)//')', missing == '')
        stray = ''
        do k = 1, size(words)
            if (index(' '//ANALYSES_ALLOWED//' ', ' '//trim(words(k))//' ') == 0) &
                stray = words(k)
        end do
        call t%check('registry: every analysis has a word of ANALYSES_ALLOWED (not: '// &
                     trim(stray)//')', stray == '' .and. size(words) > 0)
        twice = ''
        do k = 1, size(exts)
            if (count(exts == exts(k)) /= 1 .or. exts(k)(1:1) /= '.') twice = exts(k)
        end do
        call t%check('registry: each owned file extension .EXT belongs to one analysis '// &
                     '(not: '//trim(twice)//')', twice == '' .and. size(exts) >= size(words))
        twice = ''
        do k = 1, size(sweeps)
            if (count(sweeps == sweeps(k)) /= 1) twice = sweeps(k)
            do j = 1, size(exts)
                ! a checkpoint NAME.SWEEP.partial is no analysis's file
                if (trim(exts(j)) == '.'//trim(sweeps(k))//'.partial') twice = sweeps(k)
            end do
        end do
        call t%check('registry: each sweep belongs to one analysis (not: '//trim(twice)// &
                     ')', twice == '')
        call t%check('registry: an analysis that runs first has a sweep', first_ok)
    end subroutine test_registry

    !> `save` (module state, a saved local) only in the three places src/README.md names;
    !! no unused argument silenced otherwise than by `call unused(x)` (no `if (.false.)`, no
    !! `associate (unused => x)`) in src/ or tests/.
    subroutine test_state_and_idiom(t)
        type(tester_t), intent(inout) :: t
        character(len=:), allocatable :: d
        integer :: ex, n
        d = 'build/test_graph/state'
        call fresh_dir(d)
        ! code lines (not comments) with the word save, outside the three places
        ex = run('grep -rnIiE "^[^!]*\bsave\b" src --include=*.f90 | grep -v '// &
                 '-e "^src/core/signals.f90:" -e "^src/parallel/sweep_engine.f90:" '// &
                 '-e "^src/parallel/parallel_mpi.f90:"', d)
        call t%check('state: save only in signals, sweep_engine, parallel_mpi (first other: '// &
                     first_line(d//'/stdout')//')', ex == 1)
        n = shell_count('grep -lIiE "^[^!]*\bsave\b" src/core/signals.f90 '// &
                        'src/parallel/sweep_engine.f90 src/parallel/parallel_mpi.f90 | wc -l', d)
        call t%check('state: the three places keep their state with save (the check sees it)', &
                     n == 3)
        ex = run('grep -rnIiE "^[^!]*(if *\(\.false\.\)|associate *\(unused)" src tests '// &
                 '--include=*.f90', d)
        call t%check('idiom: call unused(x) is the one idiom for an unused argument (first '// &
                     'other: '// &
                     first_line(d//'/stdout')//')', ex == 1)
    end subroutine test_state_and_idiom

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
