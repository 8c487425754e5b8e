!> Robustness and daily use, through the executable of the build under test:
!! several decks per run and the worst exit status, --help and --version, --out, one
!! stderr line naming the deck, no file left by a failed run, a full disk, concurrent runs
!! of decks with the same name, bodies at rest, finite input that trapped the checking
!! build, decks that took long, the progress line, and the figures in the report.
module test_robust
    use kinds, only: dp, deg
    use output_io, only: read_kv
    use progress, only: progress_t
    use paper_claims, only: report_figures
    use testing, only: tester_t, write_text, exists, file_has, count_lines, line_starts, &
                       read_kv_text, run, shell_count, scratch_dir, fresh_dir, empty_dir, &
                       abs_path, no_nan
    use text, only: itoa
    use test_platform_analyses, only: run_platform_refusal_tests
    implicit none
    private

    public :: run_robust_tests

    character(len=*), parameter :: SCR = 'build/test_robust'
    character, parameter :: NL = new_line('a')

    ! the symmetric cylinder of input/cylinder_torsion.nml and input/cylinder_l180.nml
    character(len=*), parameter :: SUSP_EQ = &
        '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 2.0, g = 1.0 /'
    character(len=*), parameter :: SUSP_UNEQ = &
        '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 1.8, g = 1.0 /'
    character(len=*), parameter :: BODY = &
        '&body mass = 1.0, inertia = 0.125, 0.1458333333333333, 0.1458333333333333,'//NL// &
        '      r = 0.7071067811865476, lambda = 0.7853981633974483, sway_depth = 1.0 /'
    character(len=*), parameter :: SHORT = &
        '&integration tau_end = 2.0, dtau_out = 0.1, rtol = 1e-8, atol = 1e-10 /'
    !> A start at which cable BC swings up to the horizontal at tau = 0.55 (exit 4).
    character(len=*), parameter :: FLING = "&start mode = 'angles', theta_dot = 0, 0, 0, 10 /"

contains

    subroutine run_robust_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCR)
        if (t%want('robust: several decks, the worst exit status, --help, --version')) &
            call test_several(t, exe)
        if (t%want('robust: --out (empty, missing, long) and long deck paths')) &
            call test_out(t, exe)
        if (t%want('robust: one stderr line naming the deck')) call test_one_line(t, exe)
        if (t%want('robust: a failed run leaves no file')) call test_no_file_left(t, exe)
        if (t%want('robust: a full disk (tmpfs of 64 kB)')) call test_full_disk(t, exe)
        if (t%want('robust: concurrent runs of decks with the same name')) &
            call test_concurrent(t, exe)
        if (t%want('robust: bodies at rest stay at rest')) call test_rest(t, exe)
        if (t%want('robust: finite input that trapped the checking build')) &
            call test_traps(t, exe)
        if (t%want('robust: small decks that took long fail fast or are refused')) &
            call test_slow(t, exe)
        if (t%want('robust: the audit''s long decks end, refuse at once or say so')) &
            call test_audit_long(t, exe)
        if (t%want('robust: measurement mistakes refused with their cause, no file left')) &
            call test_measure_mistakes(t, exe)
        if (t%want('robust: progress on a terminal only')) call test_progress(t, exe)
        if (t%want('robust: the report shows every figure')) call test_report(t, exe)
        call run_platform_refusal_tests(t, exe)
    end subroutine run_robust_tests

    ! ---------------------------------------------------------------------------------------
    !> `bifilar a.nml b.nml ...`: each deck in turn, one stdout line per finished deck, one
    !! stderr line per failed one, exit status the largest; --help, --version, usage errors.
    subroutine test_several(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o
        integer :: ex
        d = SCR//'/several'
        call fresh_dir(d)
        o = d//'/out'
        call write_deck(d//'/ok1.nml', "&scene analyses = 'simulate' /", SUSP_EQ, '', SHORT)
        call write_deck(d//'/ok2.nml', "&scene analyses = 'simulate' /", SUSP_UNEQ, '', SHORT)
        call write_deck(d//'/bad.nml', '', '&suspension l = -1 /', '', SHORT)
        call write_deck(d//'/fling.nml', '', SUSP_EQ, FLING, SHORT)
        ex = run(exe//' '//d//'/ok1.nml '//d//'/ok2.nml --out '//o, d)
        call t%check('several: two good decks exit 0', ex == 0)
        call t%check('several: one stdout line per deck', all([count_lines(d//'/stdout') == 2, &
                     line_starts(d//'/stdout', 1, 'ok1: simulate '), &
                     line_starts(d//'/stdout', 2, 'ok2: simulate ')]))
        call t%check('several: nothing on stderr', count_lines(d//'/stderr') == 0)
        call t%check('several: both decks'' files', all([exists(o//'/ok1.dat'), &
                     exists(o//'/ok2.summary')]))
        ex = run(exe//' '//d//'/ok1.nml '//d//'/bad.nml '//d//'/fling.nml '//d// &
                 '/ok2.nml --out '//o, d)
        call t%check('several: exit status the worst of 0, 2, 4, 0 (got '//itoa(ex)//')', &
                     ex == 4)
        call t%check('several: stdout lines of the good decks only', &
                     all([count_lines(d//'/stdout') == 2, line_starts(d//'/stdout', 2, 'ok2: ')]))
        call t%check('several: one stderr line per failed deck, in order', &
                     all([count_lines(d//'/stderr') == 2, line_starts(d//'/stderr', 1, &
                     'bifilar: error (bad input): '//d//'/bad.nml: &suspension l = -1'), &
                     line_starts(d//'/stderr', 2, 'bifilar: error (model no longer valid): '// &
                     d//'/fling.nml: ')]))
        call t%check('several: no file of the failed decks', all([.not. exists(o//'/bad.dat'), &
                     .not. exists(o//'/fling.dat'), .not. exists(o//'/fling.summary')]))
        ex = run(exe//' '//d//'/bad.nml '//d//'/ok1.nml --out '//o, d)
        call t%check('several: a bad deck does not stop the next (exit 2)', all([ex == 2, &
                     count_lines(d//'/stdout') == 1]))
        ex = run(exe//' --help', d)
        call t%check('--help: exit 0, usage on stdout, nothing on stderr', all([ex == 0, &
                     file_has(d//'/stdout', 'usage: bifilar DECK.nml'), &
                     file_has(d//'/stdout', 'Exit status'), count_lines(d//'/stderr') == 0]))
        ex = run(exe//' --version', d)
        call t%check('--version: exit 0, one line "bifilar VERSION"', all([ex == 0, &
                     count_lines(d//'/stdout') == 1, line_starts(d//'/stdout', 1, 'bifilar 1')]))
        ex = run(exe, d)
        call t%check('usage: no deck is exit 1 with one stderr line', all([ex == 1, &
                     count_lines(d//'/stderr') == 1, file_has(d//'/stderr', 'usage:')]))
        ex = run(exe//' --frobnicate '//d//'/ok1.nml', d)
        call t%check('usage: an unknown option is exit 1', all([ex == 1, &
                     file_has(d//'/stderr', 'unknown option --frobnicate')]))
    end subroutine test_several

    ! ---------------------------------------------------------------------------------------
    !> --out "" is refused (it wrote into /); a missing folder is created with its parents;
    !! folder and deck names longer than 1024 characters are used whole; a file in the way
    !! is exit 5 at once.
    subroutine test_out(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, long
        integer :: ex, k
        d = SCR//'/out'
        call fresh_dir(d)
        call write_deck(d//'/robust_out_empty_test.nml', '', SUSP_EQ, '', SHORT)
        call execute_command_line('rm -f /robust_out_empty_test.dat /robust_out_empty_test.summary')
        ex = run('cd '//d//' && '//abs_path(exe)//' robust_out_empty_test.nml --out ""', d)
        call t%check('--out "": exit 1 with one stderr line', all([ex == 1, &
                     count_lines(d//'/stderr') == 1, file_has(d//'/stderr', '--out')]))
        call t%check('--out "": nothing written into / or here', &
                     all([.not. exists('/robust_out_empty_test.dat'), &
                     .not. exists(d//'/robust_out_empty_test.dat')]))
        ex = run(exe//' '//d//'/robust_out_empty_test.nml --out '//d//'/new/a/b', d)
        call t%check('--out: a missing folder is created with its parents (exit 0)', &
                     all([ex == 0, exists(d//'/new/a/b/robust_out_empty_test.dat')]))
        ! a folder name of more than 1024 characters, and a deck inside it
        long = d//'/long'
        do k = 1, 6
            long = long//'/'//repeat(achar(iachar('a') + k), 200)
        end do
        call scratch_dir(long)
        call write_deck(long//'/long_deck.nml', '', SUSP_EQ, '', SHORT)
        ex = run(exe//' '//long//'/long_deck.nml --out '//long//'/out', d)
        call t%check('long names: '//itoa(len(long//'/long_deck.nml'))//'-character deck '// &
                     'and --out: exit 0', ex == 0)
        call t%check('long names: the files where the long --out says', &
                     all([exists(long//'/out/long_deck.dat'), &
                     exists(long//'/out/long_deck.summary')]))
        call execute_command_line('rm -rf '//d//'/long')
        call write_text(d//'/a_file', 'x')
        ex = run(exe//' '//d//'/robust_out_empty_test.nml --out '//d//'/a_file', d)
        call t%check('--out: a file in the way is exit 5 with one stderr line', all([ex == 5, &
                     count_lines(d//'/stderr') == 1, file_has(d//'/stderr', 'output folder')]))
        call t%check('--out: the line names the deck and why (a regular file, not a folder)', &
                     all([file_has(d//'/stderr', 'robust_out_empty_test.nml: --out'), &
                     file_has(d//'/stderr', 'a_file is a regular file, not a folder')]))
        ex = run(exe//' '//d//'/robust_out_empty_test.nml --out '//d//'/a_file/sub', d)
        call t%check('--out: a file on the way to the folder is named', all([ex == 5, &
                     count_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'a_file is a regular file, not a folder')]))
    end subroutine test_out

    ! ---------------------------------------------------------------------------------------
    !> Every failure is exactly one stderr line 'bifilar: error (KIND): DECK: ...': no
    !! "ERROR STOP", no note on floating-point flags, the deck named even when its name
    !! occurs in the message (c.nml) and for failures of the start geometry; large values
    !! keep their E.
    subroutine test_one_line(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d
        d = SCR//'/one_line'
        call fresh_dir(d)
        ! a deck named c whose slack message contains the letter c
        call write_deck(d//'/c.nml', '', SUSP_EQ, FLING, SHORT)
        call one(d//'/c.nml', 4, 'model no longer valid', 'cable BC swings up to the horizontal')
        ! geometry failures at tau = 0
        call write_deck(d//'/theta5.nml', '', '&suspension l = 2.0, l_prime = 0.5 /', &
                        "&start mode = 'angles' /", SHORT)
        call one(d//'/theta5.nml', 2, 'bad input', 'no theta5 satisfies')
        call write_deck(d//'/reach.nml', '', '&suspension l = 0.3, l_prime = 0.3 /', &
                        '&start amplitude = 170 /', SHORT)
        call one(d//'/reach.nml', 2, 'bad input', 'cable BC cannot reach')
        ! a large value in a message keeps its E (es10.3 printed 1.000+100)
        call write_text(d//'/huge.nml', '&suspension b = 1e100, b_prime = 1e98, l = 1e98, '// &
                        'l_prime = 1e98 /'//NL//'&body mass = 1e-96, inertia = 1e99, 1e99, '// &
                        '1e99 /'//NL)
        call one(d//'/huge.nml', 2, 'bad input', 'b = 1.000E+100')
        ! a failure that leaves floating-point flags raised (a cut-short integration)
        call write_deck(d//'/rtol.nml', '', SUSP_UNEQ, '', &
                        '&integration tau_end = 2, dtau_out = 0.1, rtol = 1e-14, atol = 1e-16 /')
        call one(d//'/rtol.nml', 3, 'numerical failure', 'rtol')
        call one(d//'/no_such.nml', 2, 'bad input', 'No such file')

    contains

        subroutine one(deck, status, kind, word)
            character(len=*), intent(in) :: deck, kind, word
            integer, intent(in) :: status
            integer :: ex
            character(len=:), allocatable :: nm
            nm = deck(index(deck, '/', back=.true.) + 1:)
            ex = run(exe//' '//deck//' --out '//d//'/out', d)
            call t%check('one line: '//nm//' exit '//itoa(status)//' (got '//itoa(ex)//')', &
                         ex == status)
            call t%check('one line: '//nm//' exactly one stderr line, nothing on stdout', &
                         all([count_lines(d//'/stderr') == 1, count_lines(d//'/stdout') == 0]))
            call t%check('one line: '//nm//' "bifilar: error ('//kind//'): '//nm//': ..."', &
                         line_starts(d//'/stderr', 1, 'bifilar: error ('//kind//'): '//deck// &
                         ': '))
            call t%check('one line: '//nm//' says "'//word//'"', file_has(d//'/stderr', word))
            call t%check('one line: '//nm//' no ERROR STOP, no note on flags', &
                         all([.not. file_has(d//'/stderr', 'STOP'), &
                         .not. file_has(d//'/stderr', 'Note:')]))
        end subroutine one

    end subroutine test_one_line

    ! ---------------------------------------------------------------------------------------
    !> A failure after other analyses of the same deck wrote their files, and a failure of
    !! a precondition, leave no file of the run (and no temporary file).
    subroutine test_no_file_left(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o
        integer :: ex
        d = SCR//'/no_file'
        call fresh_dir(d)
        o = d//'/out'
        ! work_precision, then floquet, which needs equal cables: refused before computing
        call write_deck(d//'/wp_floquet.nml', "&scene analyses = 'work_precision floquet' /", &
                        SUSP_UNEQ, '', SHORT)
        ex = run(exe//' '//d//'/wp_floquet.nml --out '//o, d)
        call t%check('no file: work_precision + floquet on unequal cables is exit 2', ex == 2)
        call t%check('no file: ... says what floquet needs', all([file_has(d//'/stderr', &
                     'floquet'), file_has(d//'/stderr', 'equal cables')]))
        call t%check('no file: ... no .wp file, nothing at all', empty_dir(o))
        ! floquet (written first), then a simulation that stops: the .floquet goes too
        call write_deck(d//'/floquet_sim.nml', "&scene analyses = 'floquet simulate' /", &
                        SUSP_EQ, FLING, SHORT//NL//'&floquet rtol = 1e-6 /')
        ex = run(exe//' '//d//'/floquet_sim.nml --out '//o, d)
        call t%check('no file: floquet + failing simulate is exit 4', ex == 4)
        call t%check('no file: ... no .floquet left, nothing at all', empty_dir(o))
        ! a chart, then a simulation that stops
        call write_deck(d//'/chart_sim.nml', "&scene analyses = 'chart simulate' /", &
                        SUSP_EQ, FLING, SHORT//NL//'&floquet rtol = 1e-6 /'//NL// &
                        "&chart x = 'l', x_min = 1, x_max = 2, nx = 2, y = 'amplitude', "// &
                        'y_min = 10, y_max = 20, ny = 2 /')
        ex = run(exe//' '//d//'/chart_sim.nml --out '//o, d)
        call t%check('no file: chart + failing simulate is exit 4', ex == 4)
        call t%check('no file: ... no .chart.dat left, nothing at all', empty_dir(o))
        ! the same chart deck without the failing simulation writes its file
        call write_deck(d//'/chart_ok.nml', "&scene analyses = 'chart' /", SUSP_EQ, '', &
                        SHORT//NL//'&floquet rtol = 1e-6 /'//NL//"&chart x = 'l', x_min = 1, "// &
                        "x_max = 2, nx = 2, y = 'amplitude', y_min = 10, y_max = 20, ny = 2 /")
        ex = run(exe//' '//d//'/chart_ok.nml --out '//o, d)
        call t%check('no file: the chart alone is exit 0 and written', all([ex == 0, &
                     exists(o//'/chart_ok.chart.dat')]))
    end subroutine test_no_file_left

    ! ---------------------------------------------------------------------------------------
    !> A full disk: a tmpfs of 64 kB (needs root; skipped otherwise).  gfortran 12 reports
    !! no error when the disk fills: before this was mended the run exited 0 with a .dat cut short
    !! and an empty .summary.  Now: exit 5, one stderr line, no file (not even the .floquet
    !! that fitted); a deck that fits is written.
    subroutine test_full_disk(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, m
        integer :: ex, uid
        d = SCR//'/full_disk'
        call fresh_dir(d)
        m = d//'/disk'
        uid = shell_count('id -u', d)
        if (uid /= 0) then
            write (*, '(a)') '   full disk: skipped (mounting a tmpfs needs root; CI runs as root)'
            return
        end if
        call execute_command_line('mountpoint -q '//m//' && umount '//m//'; mkdir -p '//m)
        call execute_command_line('mount -t tmpfs -o size=64k tmpfs '//m, exitstat=ex)
        call t%check('full disk: tmpfs mounted (as root)', ex == 0)
        if (ex /= 0) return
        ex = run(exe//' input/cylinder_l180.nml --out '//m, d)
        call t%check('full disk: a 480 kB .dat on 64 kB is exit 5 (got '//itoa(ex)//')', ex == 5)
        call t%check('full disk: one stderr line naming the deck and the disk', &
                     all([count_lines(d//'/stderr') == 1, file_has(d//'/stderr', &
                     'input/cylinder_l180.nml: cannot write'), &
                     file_has(d//'/stderr', 'disk full')]))
        call t%check('full disk: no file left', empty_dir(m))
        ex = run(exe//' input/box_stable.nml --out '//m, d)
        call t%check('full disk: floquet + simulate is exit 5', ex == 5)
        call t%check('full disk: the .floquet that fitted is removed too', empty_dir(m))
        call write_deck(d//'/fits.nml', '', SUSP_EQ, '', SHORT)
        ex = run(exe//' '//d//'/fits.nml --out '//m, d)
        call t%check('full disk: a deck that fits is written (exit 0)', all([ex == 0, &
                     exists(m//'/fits.dat'), exists(m//'/fits.summary')]))
        call execute_command_line('umount '//m, exitstat=ex)
        call t%check('full disk: tmpfs unmounted', ex == 0)
    end subroutine test_full_disk

    ! ---------------------------------------------------------------------------------------
    !> Eight runs at once, four each of two different decks named same.nml, into one
    !! folder, three times: the .dat and the .summary always come from the same run (the
    !! deck line of the .dat's header is the summary's deck, the row counts agree), and no
    !! temporary file is left.  Before this was mended all runs shared same.dat.tmp.
    subroutine test_concurrent(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o, cmd, dat_deck
        integer :: round, k, rows_dat
        real(dp) :: rows_sum
        logical :: found, together, clean
        character(len=512) :: sum_deck
        d = SCR//'/concurrent'
        call fresh_dir(d)
        o = d//'/out'
        call execute_command_line('mkdir -p '//d//'/A '//d//'/B '//o)
        call write_deck(d//'/A/same.nml', '', SUSP_UNEQ, '', &
                        '&integration tau_end = 4.0, dtau_out = 0.001, rtol = 1e-8 /')
        call write_deck(d//'/B/same.nml', '', SUSP_EQ, '', &
                        '&integration tau_end = 4.0, dtau_out = 0.002, rtol = 1e-8 /')
        cmd = '('
        do k = 1, 4
            cmd = cmd//exe//' '//d//'/A/same.nml --out '//o//' >/dev/null 2>&1 & '// &
                exe//' '//d//'/B/same.nml --out '//o//' >/dev/null 2>&1 & '
        end do
        cmd = cmd//'wait)'
        together = .true.
        clean = .true.
        do round = 1, 3
            call execute_command_line(cmd)
            dat_deck = header_deck(o//'/same.dat')
            call read_kv_text(o//'/same.summary', 'deck', sum_deck)
            call read_kv(o//'/same.summary', 'rows', rows_sum, found)
            rows_dat = data_rows(o//'/same.dat')
            together = together .and. found .and. len(dat_deck) > 0 .and. &
                dat_deck == trim(sum_deck) .and. rows_dat == nint(rows_sum)
            k = count_entries(o)
            clean = clean .and. k == 2
        end do
        call t%check('concurrent: .dat and .summary of the same run, three rounds', together)
        call t%check('concurrent: no temporary file left', clean)
        call t%check('concurrent: no NaN', no_nan(o))
    end subroutine test_concurrent

    ! ---------------------------------------------------------------------------------------
    !> Bodies at rest stay at rest and exit 0 (before this was mended: exit 3 "already stands at
    !! tcrit", or exit 4 at amplitude 1e-300); an angle of 1e10 rad is refused in both
    !! builds; angles are taken modulo 2 pi.
    subroutine test_rest(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o
        integer :: ex
        real(dp) :: v, w, rows
        logical :: f1, f2, f3
        d = SCR//'/rest'
        call fresh_dir(d)
        o = d//'/out'
        call write_deck(d//'/rest.nml', '', SUSP_EQ, "&start mode = 'angles' /", &
                        '&integration tau_end = 60, dtau_out = 0.05 /')
        ex = run(exe//' '//d//'/rest.nml --out '//o, d)
        call t%check('rest: zero angles, zero rates: exit 0 (got '//itoa(ex)//')', ex == 0)
        call read_kv(o//'/rest.summary', 'max_abs_theta1', v, f1)
        call read_kv(o//'/rest.summary', 'max_abs_theta4', w, f2)
        call read_kv(o//'/rest.summary', 'rows', rows, f3)
        call t%check('rest: all 1201 rows, the body does not move', all([f1, f2, f3, &
                     v == 0.0_dp, w == 0.0_dp, nint(rows) == 1201]))
        call write_deck(d//'/small.nml', '', SUSP_EQ, '&start amplitude = 0.01 /', &
                        '&integration tau_end = 1, dtau_out = 0.05 /')
        ex = run(exe//' '//d//'/small.nml --out '//o, d)
        call t%check('rest: amplitude 0.01 deg, tau_end = 1: exit 0 (got '//itoa(ex)//')', &
                     ex == 0)
        call read_kv(o//'/small.summary', 'max_abs_theta4', w, f2)
        call t%check('rest: amplitude 0.01 deg: |theta4| <= its start', all([f2, &
                     w <= 0.01_dp*deg*(1.0_dp + 1.0e-6_dp), w > 0.0_dp]))
        call write_deck(d//'/tiny.nml', '', SUSP_EQ, '&start amplitude = 1e-300 /', &
                        '&integration tau_end = 60, dtau_out = 0.05 /')
        ex = run(exe//' '//d//'/tiny.nml --out '//o, d)
        call t%check('rest: amplitude 1e-300 deg: exit 0 (got '//itoa(ex)//')', ex == 0)
        call read_kv(o//'/tiny.summary', 'max_abs_theta4', w, f2)
        call t%check('rest: amplitude 1e-300 deg: |theta4| stays below atol (1e-12)', &
                     f2 .and. w <= 1.0e-12_dp)
        call write_deck(d//'/tilt.nml', '', SUSP_UNEQ, '&start tilt = -1e10 /', SHORT)
        ex = run(exe//' '//d//'/tilt.nml --out '//o, d)
        call t%check('rest: tilt = -1e10 is exit 2 in every build', all([ex == 2, &
                     file_has(d//'/stderr', 'tilt = -10000000000')]))
        ! tilt = 7 is tilt = 7 - 2 pi
        call write_deck(d//'/tilt7.nml', '', SUSP_UNEQ, '&start tilt = 7 /', SHORT)
        call write_deck(d//'/tilt7r.nml', '', SUSP_UNEQ, '&start tilt = 0.7168146928204138 /', &
                        SHORT)
        ex = run(exe//' '//d//'/tilt7.nml '//d//'/tilt7r.nml --out '//o, d)
        call read_kv(o//'/tilt7.summary', 'max_abs_theta1', v, f1)
        call read_kv(o//'/tilt7r.summary', 'max_abs_theta1', w, f2)
        call t%check('rest: tilt = 7 runs as tilt = 7 - 2 pi', all([ex == 0, f1, f2]))
        if (f1 .and. f2) call t%check_close('rest: tilt 7 and 7 - 2 pi: same max |theta1|', &
                                            v, w, rtol=1.0e-6_dp)
    end subroutine test_rest

    ! ---------------------------------------------------------------------------------------
    !> Finite values on which the checking build took SIGFPE: refused with exit 2 and one
    !! line, no signal, in every build.
    subroutine test_traps(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d
        character(len=80), parameter :: subs(7, 2) = reshape([character(len=80) :: &
            '&suspension b_prime = 1e300, l = 2, l_prime = 1.8 /', &
            '&suspension b_prime = 4.9e-324 /', &
            '&suspension l = 1e300 /', &
            '&suspension l = 2, l_prime = 1.8 /', &
            '&suspension l = 2, l_prime = 1.8 /', &
            '&suspension l = 2, l_prime = 1.8 /', &
            '&suspension l = 2, l_prime = 1.8 /', &
            '&body mass = 1 /', &
            '&body mass = 1 /', &
            '&body mass = 1 /', &
            '&body r = 1e300 /', &
            '&body sway_depth = 1e300 /', &
            '&body inertia = 1e-320, 0.1, 0.1 /', &
            "&body mass = 1 / &start mode = 'angles', theta_dot = 0, 0, 0, 1e308 /"], [7, 2])
        integer :: k, ex
        logical :: ok
        d = SCR//'/traps'
        call fresh_dir(d)
        ok = .true.
        do k = 1, 7
            call write_text(d//'/trap'//itoa(k)//'.nml', "&scene model = '"// &
                trim(merge('elastic', 'kane   ', k == 6))//"' /"//NL//trim(subs(k, 1))//NL// &
                trim(subs(k, 2))//NL//SHORT//NL)
            ex = run(exe//' '//d//'/trap'//itoa(k)//'.nml --out '//d//'/out', d)
            call t%check('traps: '//trim(subs(k, 1))//' '//trim(subs(k, 2))//': exit 2, one '// &
                         'line (got '//itoa(ex)//')', &
                         all([ex == 2, count_lines(d//'/stderr') == 1]))
        end do
    end subroutine test_traps

    ! ---------------------------------------------------------------------------------------
    !> Decks that took seconds to minutes (or hung) are refused or fail within seconds
    !! (`timeout` is a hang check, not a speed test): a 100 kB title line, /dev/zero,
    !! 1e7 output rows, Floquet with b = 1e-300.  A slender body (I1 = 1e-5 m b'^2) at 90
    !! degrees, 40-80 s a point before the exact Z and the structured BDF solve, is solved
    !! (exit 0, a finite multiplier, its 2 x 2 chart with no failed point); at the true edge
    !! (I1 = 1e-6, 179 degrees, rtol 1e-12, the monodromy by the variational system:
    !! sensitivities = 'differences'; the forward sensitivities solve that point) a point
    !! fails on its step budget with a message, and a chart marks such points -2.
    subroutine test_slow(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o
        character(len=*), parameter :: SLENDER = &
            '&body mass = 1.0, inertia = 1e-5, 0.1, 0.1, r = 0.7071067811865476, '// &
            'lambda = 0.7853981633974483 /'
        character(len=*), parameter :: NEEDLE = &
            '&body mass = 1.0, inertia = 1e-6, 0.1, 0.1, r = 0.7071067811865476, '// &
            'lambda = 0.7853981633974483 /'//NL//"&integration sensitivities = 'differences' /"
        real(dp) :: modulus
        logical :: found
        integer :: ex
        d = SCR//'/slow'
        call fresh_dir(d)
        o = d//'/out'
        call write_deck(d//'/title.nml', "&scene title = '"//repeat('t', 100000)//"' /", &
                        SUSP_EQ, '', SHORT)
        ex = run('timeout 20 '//exe//' '//d//'/title.nml --out '//o, d)
        call t%check('slow: a 100 kB title line is exit 2', all([ex == 2, &
                     file_has(d//'/stderr', 'longer than 4096')]))
        ex = run('timeout 20 '//exe//' /dev/zero --out '//o, d)
        call t%check('slow: /dev/zero as a deck is exit 2 (not a hang)', ex == 2)
        call write_deck(d//'/rows.nml', '', SUSP_EQ, '', &
                        '&integration tau_end = 60, dtau_out = 6e-6 /')
        ex = run('timeout 20 '//exe//' '//d//'/rows.nml --out '//o, d)
        call t%check('slow: 1e7 rows is exit 2 (row limit)', all([ex == 2, &
                     file_has(d//'/stderr', 'row limit')]))
        call write_deck(d//'/tiny_b.nml', "&scene analyses = 'floquet' /", &
                        '&suspension b = 1e-300, l = 2, l_prime = 2 /', '', SHORT)
        ex = run('timeout 20 '//exe//' '//d//'/tiny_b.nml --out '//o, d)
        call t%check('slow: Floquet with b = 1e-300 is exit 2', ex == 2)
        call write_text(d//'/slender.nml', "&scene analyses = 'floquet' /"//NL// &
                        '&suspension l = 4, l_prime = 4 /'//NL//SLENDER//NL// &
                        '&floquet amplitude = 90 /'//NL)
        ex = run('timeout 120 '//exe//' '//d//'/slender.nml --out '//o, d)
        call read_kv(o//'/slender.floquet', 'max_modulus', modulus, found)
        call t%check('slow: a slender body at 90 deg is solved (exit '//itoa(ex)// &
                     '), its largest multiplier finite and > 1', &
                     all([ex == 0, found, modulus > 1.0_dp .and. modulus < 1.0e12_dp]))
        call write_text(d//'/slender_chart.nml', "&scene analyses = 'chart' /"//NL// &
                        '&suspension l = 4, l_prime = 4 /'//NL//SLENDER//NL// &
                        "&chart x = 'l', x_min = 3.9, x_max = 4, nx = 2, y = 'amplitude', "// &
                        'y_min = 89, y_max = 90, ny = 2 /'//NL)
        ex = run('timeout 300 '//exe//' '//d//'/slender_chart.nml --out '//o, d)
        call t%check('slow: a 2 x 2 chart of the slender body is exit 0 with no failed point', &
                     all([ex == 0, .not. file_has(d//'/stdout', 'failed')]))
        call t%check('slow: ... and no -2 in it', data_rows_with(o// &
                     '/slender_chart.chart.dat', '-2.000000000000000E+000') == 0)
        call write_text(d//'/needle.nml', "&scene analyses = 'floquet' /"//NL// &
                        '&suspension l = 4, l_prime = 4 /'//NL//NEEDLE//NL// &
                        '&floquet amplitude = 179, rtol = 1e-12 /'//NL)
        ex = run('timeout 120 '//exe//' '//d//'/needle.nml --out '//o, d)
        call t%check('slow: a hopeless Floquet point is exit 3 on its step budget (got '// &
                     itoa(ex)//')', all([ex == 3, file_has(d//'/stderr', &
                     '20000 integrator steps')]))
        call write_text(d//'/needle_chart.nml', "&scene analyses = 'chart' /"//NL// &
                        '&suspension l = 4, l_prime = 4 /'//NL//NEEDLE//NL// &
                        "&chart x = 'l', x_min = 3.9, x_max = 4, nx = 2, y = 'amplitude', "// &
                        'y_min = 178.9, y_max = 179, ny = 2 /'//NL//'&floquet rtol = 1e-12 /'//NL)
        ex = run('timeout 300 '//exe//' '//d//'/needle_chart.nml --out '//o, d)
        call t%check('slow: a chart with hopeless points is exit 0, says they failed', &
                     all([ex == 0, file_has(d//'/stdout', 'failed (-2 in the file)')]))
        call t%check('slow: ... and marks them -2', data_rows_with(o// &
                     '/needle_chart.chart.dat', '-2.000000000000000E+000') >= 1)
    end subroutine test_slow

    ! ---------------------------------------------------------------------------------------
    !> The progress line: its text, nothing when stderr is a file, a line with the count on
    !! a terminal (a pseudo-terminal from script(1), when installed).
    subroutine test_progress(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(progress_t) :: pr
        character(len=:), allocatable :: d, o
        integer :: ex
        call pr%start('deck: chart', 100)
        call pr%tick(25)
        call t%check('progress: line "deck: chart: 25 of 100 (25%), ETA 30 s" after 10 s', &
                     pr%line(10.0_dp) == 'deck: chart: 25 of 100 (25%), ETA 30 s')
        call pr%tick(75)
        call t%check('progress: no ETA when done', pr%line(40.0_dp) == &
                     'deck: chart: 100 of 100 (100%)')
        call pr%finish()
        d = SCR//'/progress'
        call fresh_dir(d)
        o = d//'/out'
        call write_deck(d//'/chart.nml', "&scene analyses = 'chart' /", SUSP_EQ, '', &
                        SHORT//NL//'&floquet rtol = 1e-6 /'//NL//"&chart x = 'l', x_min = 1, "// &
                        "x_max = 2, nx = 3, y = 'amplitude', y_min = 10, y_max = 20, ny = 3 /")
        ex = run(exe//' '//d//'/chart.nml --out '//o, d)
        call t%check('progress: stderr a file: exit 0, nothing on stderr', all([ex == 0, &
                     count_lines(d//'/stderr') == 0]))
        call execute_command_line('command -v script > /dev/null || exit 1', exitstat=ex)
        if (ex /= 0) then
            write (*, '(a)') '   progress on a terminal: skipped (script(1) not installed)'
            return
        end if
        call execute_command_line('script -qec "'//exe//' '//d//'/chart.nml --out '//o// &
                                  '" /dev/null > '//d//'/tty.txt 2>&1', exitstat=ex)
        call t%check('progress: on a terminal: exit 0', ex == 0)
        call t%check('progress: on a terminal: "chart: 9 of 9 (100%)"', &
                     file_has(d//'/tty.txt', 'chart: 9 of 9 (100%)'))
    end subroutine test_progress

    ! ---------------------------------------------------------------------------------------
    !> report.md links every figure `make run` draws (one per plots/*.gp, named in the
    !! script as plots/NAME.png; plots/identify.gp draws one per identify run,
    !! plots/NAME.identify.png), relative to the report's folder.
    subroutine test_report(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o, name, up
        character(len=512) :: gp
        integer :: ex, u, ios, k, nfig
        logical :: listed
        d = SCR//'/report'
        call fresh_dir(d)
        o = d//'/out'
        ex = run(exe//' input/cylinder_l180.nml input/cylinder_l195.nml '// &
                 'input/triangle_plate.nml input/cylinder_torsion.nml --out '//o, d)
        ex = run(exe//' --report '//o, d)
        call t%check('report: written (exit 0)', all([ex == 0, exists(o//'/report.md')]))
        up = repeat('../', 4)          ! build/test_robust/report/out
        call execute_command_line('ls plots/*.gp > '//d//'/gp.txt')
        open (newunit=u, file=d//'/gp.txt', status='old', action='read', iostat=ios)
        nfig = 0
        do while (ios == 0)
            read (u, '(a)', iostat=ios) gp
            if (ios /= 0) exit
            name = gp(index(gp, '/') + 1:index(gp, '.gp') - 1)
            nfig = nfig + 1
            if (name == 'identify') then
                ! one figure per identify run, plots/NAME.identify.png: the examples'
                call t%check('report: plots/identify.gp draws plots/NAME.identify.png', &
                             file_has(trim(gp), 'plots/%s.identify.png'))
                call t%check('report: shows the identify examples'' figures', &
                             all([file_has(o//'/report.md', ']('//up// &
                                           'plots/identify_record.identify.png)'), &
                                  file_has(o//'/report.md', ']('//up// &
                                           'plots/identify_periods.identify.png)')]))
                nfig = nfig + 1
                cycle
            end if
            call t%check('report: '//trim(gp)//' draws plots/'//name//'.png', &
                         file_has(trim(gp), 'plots/'//name//'.png'))
            call t%check('report: shows ![...]('//up//'plots/'//name//'.png)', &
                         file_has(o//'/report.md', ']('//up//'plots/'//name//'.png)'))
            associate (figs => report_figures())
                listed = .false.
                do k = 1, size(figs)
                    if (figs(k)%name == name) listed = .true.
                end do
            end associate
            call t%check('report: '//name//' is one of report_figures', listed)
        end do
        close (u)
        call t%check('report: at least the 17 figures of make run', nfig >= 17)
    end subroutine test_report

    ! ---------------------------------------------------------------------------------------
    ! helpers

    !> A deck of the groups given ('' leaves a group out), BODY always.
    subroutine write_deck(path, scene, susp, start, integ)
        character(len=*), intent(in) :: path, scene, susp, start, integ
        character(len=:), allocatable :: s
        s = ''
        if (len(scene) > 0) s = s//scene//NL
        s = s//susp//NL//BODY//NL
        if (len(start) > 0) s = s//start//NL
        if (len(integ) > 0) s = s//integ//NL
        call write_text(path, s)
    end subroutine write_deck

    !> Number of entries of a folder (hidden ones included); -1 when it cannot be listed.
    integer function count_entries(dir) result(n)
        character(len=*), intent(in) :: dir
        n = shell_count('ls -A '//dir//' | wc -l', SCR)
    end function count_entries

    !> The deck path of a .dat header ('# deck PATH'); '' when absent.
    function header_deck(path) result(s)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: s
        integer :: u, ios
        character(len=1024) :: line
        s = ''
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, '# deck ') == 1) then
                s = trim(line(8:))
                exit
            end if
        end do
        close (u)
    end function header_deck

    !> Number of data lines (not '#', not blank) of a file.
    integer function data_rows(path) result(n)
        character(len=*), intent(in) :: path
        n = data_rows_with(path, '')
    end function data_rows

    !> Number of data lines (not '#', not blank) of a file that contain s.
    integer function data_rows_with(path, s) result(n)
        character(len=*), intent(in) :: path, s
        integer :: u, ios
        character(len=1024) :: line
        n = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
            if (index(line, s) > 0) n = n + 1
        end do
        close (u)
    end function data_rows_with

    ! ---------------------------------------------------------------------------------------
    !> The audit's long decks, each run alone under `timeout` (BIFILAR_NOTE_AFTER=1: the note
    !! comes after 1 s instead of 5, so that the test is short): the elastic deck of
    !! stiffness 1e12 at 170 deg spun at 100 rad per unit tau, and a tensor deck of 1e6
    !! Monte Carlo samples, each say within the timeout on one 'bifilar: note:' line what
    !! they do and how long it takes; identify of one period of 1000 s on an asymmetric rig
    !! (exit 4), a record in ms (exit 4), with a 1000 s gap (exit 2), with times from the
    !! epoch (exit 2), in deg/s read as rad/s (exit 2), and hangs timed in ms (exit 4) are
    !! refused at once with one line; 100 periods with monte_carlo = 10 say their work.
    subroutine test_audit_long(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o, x
        integer :: ex
        d = SCR//'/audit'
        o = d//'/o'
        call fresh_dir(d)
        x = abs_path(exe)
        ! the elastic deck: the note within 4 s
        call execute_command_line('sed -e "s/stiffness = 1.0e6/stiffness = 1.0e12/" -e '// &
            '"s/&start mode = .*/\&start mode = '//"'angles'"//', theta = 0, 0, 0, '// &
            '2.9670597, theta_dot = 0, 0, 0, 100 \//" input/cylinder_l180_elastic.nml > '// &
            d//'/spin.nml')
        ex = run('BIFILAR_NOTE_AFTER=1 timeout 4 '//x//' '//d//'/spin.nml --out '//o, d)
        call t%check('audit: elastic 1e12, 170 deg, spin 100: a note within 4 s (exit '// &
                     itoa(ex)//')', all([file_has(d//'/spin.nml', 'theta_dot = 0, 0, 0, 100'), &
                     count_lines(d//'/stderr', 'bifilar: note: '//d//'/spin.nml: simulate', &
                                 .true.) == 1, file_has(d//'/stderr', 'more')]))
        ! tensor with 1e6 Monte Carlo samples: the sweep's note
        call execute_command_line('sed -e "s/monte_carlo = 2000/monte_carlo = 1000000/" '// &
            '-e "s#tensor_example_hangs.csv#'//abs_path('input')//'/tensor_example_hangs.csv#" '// &
            'input/tensor_example.nml > '//d//'/mc.nml')
        ex = run('BIFILAR_NOTE_AFTER=1 timeout 5 '//x//' '//d//'/mc.nml --out '//o, d)
        call t%check('audit: tensor of 1e6 Monte Carlo samples: a note with the pace within '// &
                     '5 s (exit '//itoa(ex)//')', all([count_lines(d//'/stderr', 'bifilar: note: '// &
                     d//'/mc.nml: tensor_mc: ', .true.) == 1, file_has(d//'/stderr', &
                     'of 1000000 points after')]))
        ! identify: refused at once
        call audit_refused(t, d, o, x, 'p1000', "-e 's/l_prime = 1.20,/l_prime = 1.05,/' -e 's/periods = "// &
                     "1.41564, 1.44107, 1.52913,/periods = 1000,/' -e 's/amplitudes = 10.0, "// &
                     "30.0, 60.0,/amplitudes = 10.0,/'", 'input/identify_periods.nml', 4, &
                     'radius of gyration')
        ! a period at 179.9999 deg with u_amplitude = 0: no step across 180 deg, no NaN
        call audit_refused(t, d, o, x, 'p180', "-e 's/periods = 1.41564, 1.44107, 1.52913,/periods = 3.0,/' "// &
                     "-e 's/amplitudes = 10.0, 30.0, 60.0,/amplitudes = 179.9999,/' -e "// &
                     "'s/u_amplitude = 0.5/u_amplitude = 0/' -e 's/monte_carlo = 2000/"// &
                     "monte_carlo = 0/'", 'input/identify_periods.nml', 4, 'no rigid body')
        call t%check('audit: p180: no NaN in the message', .not. file_has(d//'/stderr', 'NaN'))
        call audit_record(t, d, o, x, 'ms', '$1*1000, $2', 4, 'likely: times in other units than s (ms)')
        call audit_record(t, d, o, x, 'gap', '($1 > 10 ? $1 + 1000 : $1), $2', 2, 'a gap of 1.000E+03 s')
        call audit_record(t, d, o, x, 'epoch', '$1 + 1.7e9, $2', 2, 'from the release')
        call audit_record(t, d, o, x, 'degs', '$1, $2*57.29577951308232', 2, 'they look like deg/s')
        call execute_command_line("awk -F, 'NR<=2{print;next}{$8=$8*1000; print}' OFS=, "// &
            'input/tensor_example_hangs.csv > '//d//'/hangs_ms.csv')
        call audit_refused(t, d, o, x, 'hangs_ms', "-e 's/tensor_example_hangs.csv/hangs_ms.csv/'", &
                     'input/tensor_example.nml', 4, '(ms)')
        ! 100 periods on an asymmetric rig with monte_carlo = 10: its work said at the start
        call execute_command_line("sed -e 's/l_prime = 1.20,/l_prime = 1.05,/' -e 's/periods"// &
            " = 1.41564, 1.44107, 1.52913,/periods = 100*1.43,/' -e 's/amplitudes = 10.0, "// &
            "30.0, 60.0,/amplitudes = 100*10.0,/' -e 's/monte_carlo = 2000/monte_carlo = 10/' "// &
            'input/identify_periods.nml > '//d//'/p100.nml')
        ex = run('BIFILAR_NOTE_AFTER=1 timeout 4 '//x//' '//d//'/p100.nml --out '//o, d)
        call t%check('audit: 100 periods, asymmetric rig, monte_carlo = 10: its work said '// &
                     'on one note line (exit '//itoa(ex)//')', all([count_lines(d//'/stderr', &
                     'bifilar: note: '//d//'/p100.nml: identify: about ', .true.) == 1, &
                     file_has(d//'/stderr', '100 periods of the full model')]))
    end subroutine test_audit_long

    !> Measurement mistakes that printed a wrong number with exit 0, each refused with one
    !! line naming its cause and no file left: a tare above all that hung; a table of
    !! periods without its column amplitude (and no &start amplitude); ten-swing totals
    !! typed as periods without &body inertia (a classical I1 above m (l^2 + b^2)); an
    !! amplitude of 1e-300 deg on unequal cables (it trapped the checking build).
    subroutine test_measure_mistakes(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o, x
        d = SCR//'/mistakes'
        o = d//'/o'
        call fresh_dir(d)
        x = abs_path(exe)
        call mistake('tare', "-e 's/u_cg_depth = 0.005/u_cg_depth = 0.005, tare_I1 = 0.05/'", &
                     'input/measure_template.nml', 2, '&measurement tare_I1 = 0.05: not below')
        call mistake('added', "-e 's/u_cg_depth = 0.005/u_cg_depth = 0.005, added_inertia"// &
                     " = 0.03/'", 'input/measure_template.nml', 2, 'added_inertia = 0.03')
        call execute_command_line("awk -F, '/^#/{print;next}{NF=5;print}' OFS=, "// &
            'input/identify_trials.csv > '//d//'/noamp.csv')
        call mistake('noamp', "-e 's#identify_trials.csv#"//abs_path(d)//"/noamp.csv#'", &
                     'input/identify_trials.nml', 2, 'no column amplitude')
        call mistake('tenswing', "-e 's/, cycles = 10//' -e 's/inertia = 0.02, 0.0118, "// &
                     "0.0121,//'", 'input/measure_template.nml', 4, 'cycles = N')
        call mistake('amp1e-300', "-e 's/l_prime = 1.0/l_prime = 1.2/' -e 's/amplitudes = "// &
                     "8, 8, 8/amplitudes = 1e-300, 1e-300, 1e-300/'", &
                     'input/measure_template.nml', 2, 'amplitudes(1) = 1e-300')
    contains
        subroutine mistake(nm, sed, base, want, word)
            character(len=*), intent(in) :: nm, sed, base, word
            integer, intent(in) :: want
            integer :: e
            call fresh_dir(o)
            call execute_command_line('sed '//sed//' '//base//' > '//d//'/'//nm//'.nml')
            e = run('timeout 60 '//x//' '//d//'/'//nm//'.nml --out '//o, d)
            call t%check('mistakes: '//nm//': exit '//itoa(e)//' (want '//itoa(want)// &
                         '), one line saying "'//word//'", no file', all([e == want, &
                         count_lines(d//'/stderr') == 1, file_has(d//'/stderr', word), &
                         count_lines(d//'/stderr', 'bifilar: error (', .true.) == 1, &
                         empty_dir(o)]))
        end subroutine mistake
    end subroutine test_measure_mistakes

    !> A deck made by sed from base: exit status want and one line holding word.
    subroutine audit_refused(t, d, o, x, nm, sed, base, want, word)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: d, o, x, nm, sed, base, word
        integer, intent(in) :: want
        integer :: e
        call execute_command_line('sed '//sed//' '//base//' > '//d//'/'//nm//'.nml')
        e = run('timeout 10 '//x//' '//d//'/'//nm//'.nml --out '//o, d)
        call t%check('audit: '//nm//': refused at once, exit '//itoa(e)//' (want '// &
                     itoa(want)//'), one line saying "'//word//'"', all([e == want, &
                     count_lines(d//'/stderr') == 1, file_has(d//'/stderr', word), &
                     count_lines(d//'/stderr', 'bifilar: error (', .true.) == 1]))
    end subroutine audit_refused

    !> The example record rewritten by awk (columns expr), in a copy of its deck.
    subroutine audit_record(t, d, o, x, nm, expr, want, word)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: d, o, x, nm, expr, word
        integer, intent(in) :: want
        call execute_command_line("awk '/^#/{print;next}{printf ""%.6f %s\n"", "// &
            expr//"}' input/identify_record_swing.dat > "//d//'/rec_'//nm//'.dat')
        call audit_refused(t, d, o, x, 'r_'//nm, "-e 's/identify_record_swing.dat/rec_"// &
                           nm//".dat/'", 'input/identify_record.nml', want, word)
    end subroutine audit_record


end module test_robust
