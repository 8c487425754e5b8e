!> A tare read from its own output (&measurement tare = 'FILE'), with truths made here: a
!! fixture (I1 = 0.02) swung alone on a rig, then with a body on it (all that hung 0.08).
!! The tare from its file and the direct difference of the two outputs' I1 agree; the
!! correlated u is below the uncorrelated one (tare_I1 with its u typed) by exactly the
!! shared inputs' share, sum 2 c_loaded c_tare u^2, computed by hand from the two outputs'
!! budgets; the tare's own Type A part keeps its degrees of freedom; over 20 seeds of
!! timing noise and tape errors (one tape for both runs) the body's U covers its truth in
!! at least 17; a missing file, one that is not an identify output, a tare of another rig
!! and a tare given twice are refused with one line, exit 2 and no output.
module test_tare
    use kinds, only: dp
    use testing, only: tester_t, write_text, run, fresh_dir, exists, message_lines, &
        noisy, true_periods, periods_text, full => full_text
    use random, only: rng_t, rng_stream, rng_normal
    use output_io, only: read_kv
    use text, only: rshort, itoa
    implicit none
    private
    public :: run_tare_tests

    character(len=*), parameter :: DIR = 'build/test_tare'
    real(dp), parameter :: U_T = 1.0e-4_dp, U_L = 1.0e-3_dp, U_B = 5.0e-4_dp
    real(dp), parameter :: I_FIX_TRUE = 0.02_dp, I_ALL_TRUE = 0.08_dp
    real(dp), parameter :: M_FIX = 1.0_dp, M_ALL = 3.2_dp
    real(dp), parameter :: AMPS(3) = [10.0_dp, 20.0_dp, 30.0_dp]
    character(len=8), parameter :: SHARED(4) = [character(len=8) :: 'l', 'l_prime', 'b', &
        'b_prime']

contains

    subroutine run_tare_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp) :: tfix(3), tall(3), tape(4)
        real(dp) :: i_file, u_file, i_all, i_tare, u_tare, i_typed, u_typed, big_u, share
        real(dp) :: cl, ct, ux, dof, dof_own, uo_tare, uo_loaded, dof_loaded, dof_hand
        real(dp) :: u_total, u_all
        integer :: seed, covered, ex, j
        logical :: ok, found, f1, f2
        if (.not. t%want('tare: a tare from its own output, with the shared inputs correlated')) &
            return
        call fresh_dir(DIR)
        call true_periods(DIR, 'fix', M_FIX, I_FIX_TRUE, AMPS, tfix, ok)
        call true_periods(DIR, 'all', M_ALL, I_ALL_TRUE, AMPS, tall, ok)
        call t%check('tare: true periods made', ok)
        if (.not. ok) return
        ! seed 1, the taped rig exact: the three ways against each other
        tape = [1.2_dp, 1.2_dp, 0.4_dp, 0.4_dp]
        ok = run_pair(exe, 1, tape, tfix, tall)
        call t%check('tare: the tare''s deck and the loaded deck with tare = ''FILE'' run', ok)
        if (.not. ok) return
        call write_text(DIR//'/all.nml', head('all', M_ALL, tape)// &
                        periods_text(noisy(tall, U_T, 1, 2))//' /'//new_line('a'))
        ex = run(exe//' '//DIR//'/all.nml --out '//DIR, DIR)
        call read_kv(DIR//'/all.identify', 'I1', i_all, f1)
        call read_kv(DIR//'/tare.identify', 'I1', i_tare, f2)
        call read_kv(DIR//'/tare.identify', 'u_I1', u_tare, found)
        call read_kv(DIR//'/loaded.identify', 'I1', i_file, ok)
        call read_kv(DIR//'/loaded.identify', 'u_I1', u_file, ok)
        call t%check('tare: the outputs of all that hung and of the tare read', &
                     ex == 0 .and. f1 .and. f2 .and. found .and. ok)
        call t%check_close('tare: I1 from the tare''s file = I1(all that hung) - I1(tare)', &
                           i_file, i_all - i_tare, rtol=1.0e-9_dp)
        call read_kv(DIR//'/loaded.identify', 'u_I1_total', u_total, f1)
        call read_kv(DIR//'/all.identify', 'u_I1', u_all, f2)
        call t%check('tare: u_I1_total and u_I1 of all that hung read', f1 .and. f2)
        call t%check_close('tare: u_I1_total is that of all that hung alone (its own '// &
                           'sensitivities)', u_total, u_all, rtol=1.0e-9_dp)
        call write_text(DIR//'/typed.nml', head('typed', M_ALL, tape)// &
                        periods_text(noisy(tall, U_T, 1, 2))//', tare_I1 = '//full(i_tare)// &
                        ', u_tare_I1 = '//full(u_tare)//' /'//new_line('a'))
        ex = run(exe//' '//DIR//'/typed.nml --out '//DIR, DIR)
        call read_kv(DIR//'/typed.identify', 'I1', i_typed, f1)
        call read_kv(DIR//'/typed.identify', 'u_I1', u_typed, f2)
        call t%check('tare: the typed tare runs', ex == 0 .and. f1 .and. f2)
        call t%check_close('tare: the typed tare gives the same I1', i_typed, i_file, &
                           rtol=1.0e-9_dp)
        call t%check('tare: the correlated u ('//rshort(u_file)//') below the uncorrelated ('// &
                     rshort(u_typed)//')', u_file < u_typed)
        ! the shared inputs' share, by hand from the two outputs' budget rows
        share = 0.0_dp
        ok = .true.
        do j = 1, size(SHARED)
            call budget_row(DIR//'/all.identify', SHARED(j), ux, cl, f1)
            call budget_row(DIR//'/tare.identify', SHARED(j), ux, ct, f2)
            ok = ok .and. f1 .and. f2
            share = share + 2.0_dp*cl*ct*ux**2
        end do
        call t%check('tare: both outputs carry the shared inputs'' rows', ok)
        call t%check_close('tare: u_typed^2 - u_file^2 = sum 2 c_loaded c_tare u^2 (the '// &
                           'shared inputs'' share)', u_typed**2 - u_file**2, share, &
                           rtol=1.0e-6_dp)
        call t%check('tare: the shared share is a real part of u (above 10 % of u_typed^2)', &
                     share > 0.1_dp*u_typed**2)
        ! the tare's own Type A part keeps its degrees of freedom: periods without
        ! u_period (u from their scatter) in the tare's deck
        call write_text(DIR//'/tare.nml', head('tare', M_FIX, tape, 0.0_dp)// &
                        periods_text(tfix + [2.0e-3_dp, -2.0e-3_dp, 1.0e-3_dp])//', '// &
                        rshort(tfix(1) - 2.0e-3_dp)//', amplitudes = 10, 20, 30, 10 /'// &
                        new_line('a'))
        ex = run(exe//' '//DIR//'/tare.nml --out '//DIR, DIR)
        call read_kv(DIR//'/tare.identify', 'dof_own', dof_own, f1)
        call read_kv(DIR//'/tare.identify', 'u_I1_own', uo_tare, f2)
        call t%check('tare: the tare''s deck with u from the scatter runs, dof_own = 3', &
                     ex == 0 .and. f1 .and. f2 .and. abs(dof_own - 3.0_dp) < 1.0e-9_dp)
        call write_text(DIR//'/loaded.nml', head('loaded', M_ALL, tape)// &
                        periods_text(noisy(tall, U_T, 1, 2))//', tare = ''tare.identify'' /'// &
                        new_line('a'))
        ex = run(exe//' '//DIR//'/loaded.nml --out '//DIR, DIR)
        call read_kv(DIR//'/loaded.identify', 'dof_eff', dof, f1)
        call read_kv(DIR//'/loaded.identify', 'u_I1', u_file, f2)
        call read_kv(DIR//'/loaded.identify', 'u_I1_own', uo_loaded, found)
        call read_kv(DIR//'/loaded.identify', 'dof_own', dof_loaded, ok)
        ! Welch-Satterthwaite by hand: the two own parts, every input infinite
        dof_hand = u_file**4/(uo_tare**4/dof_own + uo_loaded**4/dof_loaded)
        call t%check_close('tare: the body''s dof_eff ('//rshort(dof)//') is Welch-'// &
                           'Satterthwaite''s with the tare''s own dof kept', dof, dof_hand, &
                           rtol=1.0e-6_dp)
        call t%check('tare: the tare''s own part makes dof_eff finite ('//rshort(dof)//')', &
                     ex == 0 .and. f1 .and. f2 .and. found .and. ok .and. dof < 1.0e5_dp)
        ! coverage: one tape for both runs, drawn per seed
        covered = 0
        do seed = 1, 20
            tape = tape_of(seed)
            ok = run_pair(exe, seed, tape, tfix, tall)
            call read_kv(DIR//'/loaded.identify', 'I1', i_file, f1)
            call read_kv(DIR//'/loaded.identify', 'U_I1', big_u, f2)
            if (.not. (ok .and. f1 .and. f2)) then
                call t%check('tare: seed '//itoa(seed)//' runs', .false.)
                return
            end if
            if (abs(i_file - (I_ALL_TRUE - I_FIX_TRUE)) <= big_u) covered = covered + 1
        end do
        call t%check('tare: over 20 seeds the body''s U covers its truth in >= 17 ('// &
                     itoa(covered)//')', covered >= 17)
        call refusals(t, exe, tfix, tall)
        call calibrated(t, exe, tfix, tall)
    end subroutine run_tare_tests

    !> Both runs on one calibration: its row enters once, with the body's sensitivity
    !! (I1/scale), and a tare without the loaded run's calibration is refused.
    subroutine calibrated(t, exe, tfix, tall)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp), intent(in) :: tfix(3), tall(3)
        real(dp), parameter :: SCALE = 1.001_dp, U_SCALE = 1.0e-3_dp
        real(dp) :: tape(4), i_body, i_total, i_tare, ux, c
        integer :: ex1, ex2, ex3
        logical :: f1, f2, f3, f4, one, none
        tape = [1.2_dp, 1.2_dp, 0.4_dp, 0.4_dp]
        call write_text(DIR//'/cal.calibration', 'delta_l = 0'//new_line('a')//'scale = '// &
            full(SCALE)//new_line('a')//'var_delta_l = 0'//new_line('a')//'var_scale = '// &
            full(U_SCALE**2)//new_line('a')//'cov_delta_l_scale = 0'//new_line('a')// &
            'delta_l_estimated = 0'//new_line('a')//'l = 1.2'//new_line('a'))
        call write_text(DIR//'/ctare.nml', head('ctare', M_FIX, tape)//periods_text(tfix)// &
                        ', calibration = ''cal.calibration'' /'//new_line('a'))
        ex1 = run(exe//' '//DIR//'/ctare.nml --out '//DIR, DIR)
        call write_text(DIR//'/cload.nml', head('cload', M_ALL, tape)//periods_text(tall)// &
            ', calibration = ''cal.calibration'', tare = ''ctare.identify'' /'//new_line('a'))
        ex2 = run(exe//' '//DIR//'/cload.nml --out '//DIR, DIR)
        call read_kv(DIR//'/cload.identify', 'I1', i_body, f1)
        call read_kv(DIR//'/cload.identify', 'I1_total', i_total, f2)
        call read_kv(DIR//'/ctare.identify', 'I1', i_tare, f3)
        call budget_row(DIR//'/cload.identify', 'calibration', ux, c, f4)
        call t%check('tare: on one calibration both decks run', ex1 == 0 .and. ex2 == 0 .and. &
                     f1 .and. f2 .and. f3 .and. f4)
        call t%check_close('tare: on one calibration, I1 = I1_total - I1_tare', i_body, &
                           i_total - i_tare, rtol=1.0e-9_dp)
        call t%check_close('tare: the calibration''s row once, with the body''s sensitivity '// &
                           'I1/scale', c, i_body/SCALE, rtol=1.0e-6_dp)
        ! the tare without the calibration
        call write_text(DIR//'/ctare.nml', head('ctare', M_FIX, tape)//periods_text(tfix)// &
                        ' /'//new_line('a'))
        ex1 = run(exe//' '//DIR//'/ctare.nml --out '//DIR, DIR)
        call execute_command_line('rm -f '//DIR//'/cload.identify')
        ex3 = run(exe//' '//DIR//'/cload.nml --out '//DIR, DIR)
        one = message_lines(DIR//'/stderr') == 1
        none = .not. exists(DIR//'/cload.identify')
        call t%check('tare: a tare without the loaded run''s calibration refused: exit 2, one '// &
                     'line, no output', ex1 == 0 .and. ex3 == 2 .and. one .and. none)
    end subroutine calibrated

    !> The refusals: one line, exit 2, no output of the loaded deck.
    subroutine refusals(t, exe, tfix, tall)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        real(dp), intent(in) :: tfix(3), tall(3)
        real(dp) :: tape(4)
        integer :: ex
        logical :: one, none, named
        tape = [1.2_dp, 1.2_dp, 0.4_dp, 0.4_dp]
        ! the tare's output of this rig, and one of another (l 5 cm longer)
        call write_text(DIR//'/tare.nml', head('tare', M_FIX, tape)// &
                        periods_text(tfix)//' /'//new_line('a'))
        ex = run(exe//' '//DIR//'/tare.nml --out '//DIR, DIR)
        call write_text(DIR//'/other.nml', head('other', M_FIX, tape + [0.05_dp, 0.05_dp, &
                        0.0_dp, 0.0_dp])//periods_text(tfix)//' /'//new_line('a'))
        ex = run(exe//' '//DIR//'/other.nml --out '//DIR, DIR)
        call refused(t, exe, 'a missing file', 'tare = ''none.identify''', tall)
        call refused(t, exe, 'not an identify output', 'tare = ''tare.nml''', tall)
        call refused(t, exe, 'a tare of another rig', 'tare = ''other.identify''', tall)
        call refused(t, exe, 'tare and tare_I1', 'tare = ''tare.identify'', tare_I1 = 0.02, '// &
                     'u_tare_I1 = 1e-4', tall)
        ! a tensor deck: its fit takes no tare of identify's one axis
        call execute_command_line('cp input/tensor_example_hangs.csv '//DIR//'/ && sed -e '// &
            '"s/monte_carlo = 2000/monte_carlo = 0/" input/tensor_example.nml > '//DIR// &
            '/tens.nml && echo "&measurement tare = ''tare.identify'' /" >> '//DIR//'/tens.nml')
        call execute_command_line('rm -f '//DIR//'/tens.tensor')
        ex = run(exe//' '//DIR//'/tens.nml --out '//DIR, DIR)
        one = message_lines(DIR//'/stderr') == 1
        none = .not. exists(DIR//'/tens.tensor')
        named = stderr_has('&measurement tare')
        call t%check('tare: a tare''s output in a tensor deck refused: exit 2, one line, no '// &
                     'output', ex == 2 .and. one .and. none .and. named)
    end subroutine refusals

    subroutine refused(t, exe, what, words, tall)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe, what, words
        real(dp), intent(in) :: tall(3)
        integer :: ex
        logical :: one, none, named
        call write_text(DIR//'/bad.nml', head('bad', M_ALL, [1.2_dp, 1.2_dp, 0.4_dp, 0.4_dp])// &
                        periods_text(tall)//', '//words//' /'//new_line('a'))
        call execute_command_line('rm -f '//DIR//'/bad.identify')
        ex = run(exe//' '//DIR//'/bad.nml --out '//DIR, DIR)
        one = message_lines(DIR//'/stderr') == 1
        none = .not. exists(DIR//'/bad.identify')
        named = stderr_has('&measurement tare')
        call t%check('tare: '//what//' refused: exit 2, one line naming &measurement tare, '// &
                     'no output', ex == 2 .and. one .and. none .and. named)
    end subroutine refused

    logical function stderr_has(word)
        character(len=*), intent(in) :: word
        integer :: u, ios
        character(len=2048) :: line
        stderr_has = .false.
        open (newunit=u, file=DIR//'/stderr', status='old', action='read', iostat=ios)
        if (ios /= 0) return
        read (u, '(a)', iostat=ios) line
        if (ios == 0) stderr_has = index(line, word) > 0
        close (u)
    end function stderr_has

    !> The tare's deck and the loaded deck taking its output, on taped rig `tape`.
    logical function run_pair(exe, seed, tape, tfix, tall) result(ok)
        character(len=*), intent(in) :: exe
        integer, intent(in) :: seed
        real(dp), intent(in) :: tape(4), tfix(3), tall(3)
        integer :: ex
        call write_text(DIR//'/tare.nml', head('tare', M_FIX, tape)// &
                        periods_text(noisy(tfix, U_T, seed, 1))//' /'//new_line('a'))
        ex = run(exe//' '//DIR//'/tare.nml --out '//DIR, DIR)
        ok = ex == 0
        call write_text(DIR//'/loaded.nml', head('loaded', M_ALL, tape)// &
                        periods_text(noisy(tall, U_T, seed, 2))//', tare = ''tare.identify'' /'// &
                        new_line('a'))
        ex = run(exe//' '//DIR//'/loaded.nml --out '//DIR, DIR)
        ok = ok .and. ex == 0
    end function run_pair

    !> A tape's readings of l, l', b, b' (each within its u of the truth), the same for
    !! both runs of a seed.
    function tape_of(seed) result(x)
        integer, intent(in) :: seed
        real(dp) :: x(4)
        type(rng_t) :: g
        g = rng_stream(seed, 7)
        x(1) = 1.2_dp + U_L*rng_normal(g)
        x(2) = 1.2_dp + U_L*rng_normal(g)
        x(3) = 0.4_dp + U_B*rng_normal(g)
        x(4) = 0.4_dp + U_B*rng_normal(g)
    end function tape_of

    !> A deck's head on the taped rig (l, l', b, b' = tape); u_period given unless 0.
    function head(name, mass, tape, u_period) result(s)
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: mass, tape(4)
        real(dp), intent(in), optional :: u_period
        character(len=:), allocatable :: s
        real(dp) :: up
        up = U_T
        if (present(u_period)) up = u_period
        s = '&scene title = '''//name//''', analyses = ''identify'' /'//new_line('a')// &
            '&suspension b = '//rshort(tape(3))//', b_prime = '//rshort(tape(4))// &
            ', l = '//rshort(tape(1))//', l_prime = '//rshort(tape(2))//', g = 9.80665 /'// &
            new_line('a')//'&body mass = '//rshort(mass)//', inertia = 0.05, 0.05, 0.04, '// &
            'cg_depth = 0.02, cg_offset = 0.0 /'//new_line('a')// &
            '&measurement u_mass = 0.001, u_l = '//rshort(U_L)//', u_l_prime = '//rshort(U_L)// &
            ', u_b = '//rshort(U_B)//', u_b_prime = '//rshort(U_B)
        if (up > 0.0_dp) then
            s = s//', u_period = '//rshort(up)//', amplitudes = 10, 20, 30,'
        else
            s = s//','
        end if
    end function head

    !> The budget row `name` of an identify output: its u and sensitivity.
    subroutine budget_row(path, name, u_x, c, found)
        character(len=*), intent(in) :: path, name
        real(dp), intent(out) :: u_x, c
        logical, intent(out) :: found
        integer :: u, ios
        character(len=512) :: line
        real(dp) :: f(4)
        logical :: in_budget
        found = .false.
        u_x = 0.0_dp
        c = 0.0_dp
        in_budget = .false.
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, '# budget of I1') == 1) in_budget = .true.
            if (.not. in_budget .or. line(1:1) == '#') cycle
            if (trim(line(1:14)) /= trim(name)) cycle
            read (line(15:), *, iostat=ios) f
            found = ios == 0
            u_x = f(2)
            c = f(3)
            exit
        end do
        close (u)
    end subroutine budget_row

end module test_tare
