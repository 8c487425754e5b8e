!> Tests of the deck group &output (columns): a subset of the .dat columns keeps their order
!! and their text, an unknown or repeated name is a deck error of one line, the default is
!! every column, and the summary keeps the keys of what the run computed.
module test_columns
    use kinds, only: dp
    use status, only: status_t, ERR_DECK
    use testing, only: tester_t, write_text, scratch_dir
    use deck, only: deck_t, read_deck, OUTPUT_COLUMNS
    use simulate, only: run_simulation, run_summary_t
    use output_io, only: read_kv
    implicit none
    private

    public :: run_columns_tests

    character(len=*), parameter :: SCRATCH = 'build/test_columns'
    character, parameter :: NL = new_line('a')
    !> A short run of the Figs. 4-6 cylinder (unequal cables: tilting, sway, tensions vary)
    character(len=*), parameter :: SCENE = &
        '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 1.8 /'//achar(10)// &
        '&body mass = 1.0, inertia = 0.125, 0.1458333333333333, 0.1458333333333333, '// &
        'r = 0.7071067811865476, lambda = 0.7853981633974483 /'//achar(10)// &
        '&integration tau_end = 6.0, dtau_out = 0.05, rtol = 1e-10, atol = 1e-12 /'

contains

    subroutine run_columns_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCRATCH)
        if (t%want('columns: a subset keeps the order and the text of the full run')) &
            call test_subset(t)
        if (t%want('columns: default every column; the paper decks keep all')) &
            call test_default(t)
        if (t%want('columns: unknown, repeated or no name is a deck error')) &
            call test_bad_names(t, exe)
    end subroutine run_columns_tests

    !> The same run with every column and with 'Q theta4 TAU' (any order, any case): the
    !! subset's header is '# tau theta4 Q' and each of its rows is the full row's columns
    !! 1, 5, 12, character for character; the summary has max_Q but no energy, residual keys,
    !! and its min_tension (from the integrator's derivative) is the full run's to 1e-7.
    subroutine test_subset(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(status_t) :: st
        type(run_summary_t) :: sm_all, sm_sub
        character(len=512) :: hdr_all, hdr_sub
        character(len=512), allocatable :: rows_all(:), rows_sub(:)
        real(dp) :: v
        logical :: found, same
        integer :: k, n
        call write_text(SCRATCH//'/all.nml', SCENE//NL)
        call write_text(SCRATCH//'/sub.nml', SCENE//NL//'&output columns = ''Q theta4 TAU'' /'// &
                        NL)
        call read_deck(SCRATCH//'/all.nml', d, st)
        if (st%code == 0) call run_simulation(d, SCRATCH, sm_all, st)
        call t%check('full run', st%code == 0)
        call read_deck(SCRATCH//'/sub.nml', d, st)
        call t%check('subset deck reads, columns in the file''s order: '//trim(d%output%columns), &
                     st%code == 0 .and. trim(d%output%columns) == 'tau theta4 Q')
        if (st%code == 0) call run_simulation(d, SCRATCH, sm_sub, st)
        call t%check('subset run', st%code == 0)
        call read_dat(SCRATCH//'/all.dat', hdr_all, rows_all)
        call read_dat(SCRATCH//'/sub.dat', hdr_sub, rows_sub)
        call t%check('full header is every column in order', trim(hdr_all) == '# '//OUTPUT_COLUMNS)
        call t%check('subset header: '//trim(hdr_sub), trim(hdr_sub) == '# tau theta4 Q')
        n = size(rows_sub)
        same = n == size(rows_all) .and. n == 121
        do k = 1, min(n, size(rows_all))
            same = same .and. len_trim(rows_sub(k)) == 14 + 2*24
            same = same .and. rows_sub(k)(1:14) == rows_all(k)(1:14)
            same = same .and. rows_sub(k)(15:38) == rows_all(k)(14 + 3*24 + 1:14 + 4*24)
            same = same .and. rows_sub(k)(39:62) == rows_all(k)(14 + 10*24 + 1:14 + 11*24)
        end do
        call t%check('subset rows are the full rows'' tau, theta4, Q (121 rows, same text)', &
                     same)
        call read_kv(SCRATCH//'/sub.summary', 'max_Q', v, found)
        call t%check_close('subset summary: max_Q as the full run''s', v, sm_all%max_q, &
                           rtol=0.0_dp)
        call read_kv(SCRATCH//'/sub.summary', 'max_abs_energy_error', v, found)
        call t%check('subset summary: no energy key (not computed)', .not. found)
        call read_kv(SCRATCH//'/sub.summary', 'max_abs_constraint_residual', v, found)
        call t%check('subset summary: no residual key (not computed)', .not. found)
        call t%check_close('subset min_tension (integrator''s derivative) = full run''s', &
                           sm_sub%min_tension, sm_all%min_tension, rtol=1.0e-7_dp)
    end subroutine test_subset

    !> Without &output every column is written, in OUTPUT_COLUMNS' order; the paper decks,
    !! whose columns paper_claims and the figures read, ask for no subset.
    subroutine test_default(t)
        type(tester_t), intent(inout) :: t
        character(len=20), parameter :: decks(6) = [character(len=20) :: 'cylinder_l180', &
            'cylinder_l195', 'triangle_plate', 'cylinder_torsion', 'box_stable', 'box_unstable']
        type(deck_t) :: d
        type(status_t) :: st
        integer :: k
        call write_text(SCRATCH//'/plain.nml', SCENE//NL)
        call read_deck(SCRATCH//'/plain.nml', d, st)
        call t%check('no &output: every column', st%code == 0 .and. &
                     d%output%columns == OUTPUT_COLUMNS)
        do k = 1, size(decks)
            call read_deck('input/'//trim(decks(k))//'.nml', d, st)
            call t%check(trim(decks(k))//' writes every column', &
                         st%code == 0 .and. d%output%columns == OUTPUT_COLUMNS)
        end do
    end subroutine test_default

    !> Through the executable: exit status 2, one line on stderr naming the deck, the group,
    !! the variable, the value and the allowed names; no .dat left.
    subroutine test_bad_names(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        call bad('unknown', 'tau theta1 phi', 'unknown column ''phi''')
        call bad('twice', 'tau theta1 THETA1', 'given twice')
        call bad('none', '', 'no column given')
    contains
        subroutine bad(name, value, what)
            character(len=*), intent(in) :: name, value, what
            character(len=:), allocatable :: path, log
            character(len=2048) :: line
            integer :: ex, u, ios, nlines
            logical :: there, named
            path = SCRATCH//'/bad_'//name//'.nml'
            log = SCRATCH//'/bad_'//name//'.log'
            call write_text(path, SCENE//NL//'&output columns = '''//value//''' /'//NL)
            call execute_command_line(exe//' '//path//' --out '//SCRATCH//' > '//log// &
                                      ' 2>&1', exitstat=ex)
            call t%check('&output '//name//': exit status 2', ex == ERR_DECK)
            inquire (file=SCRATCH//'/bad_'//name//'.dat', exist=there)
            call t%check('&output '//name//': no .dat left', .not. there)
            named = .false.
            nlines = 0
            open (newunit=u, file=log, status='old', action='read', iostat=ios)
            do while (ios == 0)
                read (u, '(a)', iostat=ios) line
                if (ios /= 0) exit
                ! the program's message (not the run-time library's error-stop lines)
                if (index(line, 'bifilar:') /= 1) cycle
                nlines = nlines + 1
                named = index(line, 'bad_'//name) > 0 .and. index(line, '&output columns') > 0 &
                        .and. index(line, what) > 0 .and. index(line, 'allowed') > 0 .and. &
                        index(line, 'constraint_residual') > 0
            end do
            close (u)
            call t%check('&output '//name//': one line naming deck, group, variable, '// &
                         'value and the allowed names', named .and. nlines == 1)
        end subroutine bad
    end subroutine test_bad_names

    !> The column line (last '#' line) and the data rows of a .dat file.
    subroutine read_dat(path, header, rows)
        character(len=*), intent(in) :: path
        character(len=*), intent(out) :: header
        character(len=512), allocatable, intent(out) :: rows(:)
        character(len=512) :: line
        character(len=512), allocatable :: tmp(:)
        integer :: u, ios, n
        header = ''
        allocate (tmp(100000))
        n = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#') then
                header = line
            else if (len_trim(line) > 0) then
                n = n + 1
                tmp(n) = line
            end if
        end do
        if (ios <= 0) close (u)
        rows = tmp(1:n)
    end subroutine read_dat

end module test_columns
