!> Measurement as it is done (analysis identify on real-world inputs): tables as
!! instruments write them, the pooling of releases, the traps that must not give a number
!! (exit 2 or 4, one line), a phone's gyro CSV (header, five columns, deg/s, a bias, the
!! release 1.4 s in), timed totals of several cycles, the mass centre as measured (cg_depth)
!! against r and lambda, a trifilar platform against an independent quadrature of its
!! torsion, a tare, trials that disagree, the 95 % interval's coverage over releases that
!! scatter more than their own uncertainty says, and the one measurement model (a release's
!! own estimate, on_failure, sessions, one table reader).  Truths are made here: periods by the
!! exact torsion period (or the quadrature), records by the model with noise drawn here.
module test_measure
    use kinds, only: dp, pi, deg
    use status, only: status_t
    use testing, only: tester_t, write_text, file_has, count_lines, run, fresh_dir, &
        read_kv_text, message_lines
    use deck, only: deck_t, read_deck_text
    use deck_runs, only: rig_of, start_of, accuracy_of, deck_inputs
    use measurement, only: measurement_t
    use measurement_read, only: read_releases, read_hangs
    use driver, only: run_deck
    use identify, only: warning_t
    use random, only: rng_t, rng_stream, rng_normal
    use period_inversion, only: torsion_period_s
    use record_fit, only: record_model, correlation_time
    use tables, only: table_t, read_table
    use pooling, only: pooled_t, pool_releases
    use stats, only: NU_INFINITE
    use output_io, only: read_kv
    use text, only: itoa
    implicit none
    private

    public :: run_measure_tests

    character(len=*), parameter :: SCR = 'build/test_measure'
    character(len=*), parameter :: NL = new_line('a')
    real(dp), parameter :: I1_TRUE = 0.0512_dp
    !> A laboratory rig in SI units, symmetric (equal cables, the mass centre on the axis).
    character(len=*), parameter :: SUSP = &
        '&suspension b = 0.4, b_prime = 0.4, l = 1.2, l_prime = 1.2, g = 9.80665 /'//NL
    character(len=*), parameter :: BODY = &
        '&body mass = 3.1, inertia = 0.0512, 0.063, 0.0304, cg_depth = 0.15 /'//NL
    character(len=*), parameter :: HEAD = "&scene title = 'measure test', "// &
        "analyses = 'identify' /"//NL

contains

    !> Suite measure.
    subroutine run_measure_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        call fresh_dir(SCR)
        if (t%want('measure: tables as instruments write them, text columns')) call test_tables(t)
        if (t%want('measure: pooling of releases')) call test_pooling(t)
        if (t%want('measure: traps refused with one line')) call test_traps(t, exe)
        if (t%want('measure: cycles, tare, cg_depth against r and lambda')) call test_decks(t)
        if (t%want('measure: trifilar against its own quadrature')) call test_trifilar(t)
        if (t%want('measure: phone gyro CSV, bias, release 1.4 s in')) call test_phone(t, exe)
        if (t%want('measure: trials, consistent and not')) call test_trials(t, exe)
        if (t%want('measure: one model: per-release estimate, on_failure, sessions, one '// &
                   'table reader')) call test_model(t, exe)
        if (t%want('measure: coverage over releases that scatter')) call test_coverage(t)
        if (t%want('measure: sessions: coverage in two levels')) call test_sessions(t)
        if (t%want('measure: correlated residuals')) call test_correlated(t)
        if (t%want('measure: video track from mid-swing, glitches, huber')) call test_video(t)
        if (t%want('measure: no figure script carries a deck''s title')) call test_titles(t)
        if (t%want('measure: records by frame, by name, with text, a gyro export')) &
            call test_reader(t, exe)
        if (t%want('measure: record mistakes refused at once or warned')) &
            call test_record_mistakes(t, exe)
    end subroutine run_measure_tests

    !> A number as deck text (full precision).
    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: b
        write (b, '(es24.16)') x
        s = trim(adjustl(b))
    end function num

    !> The exact torsion period (s) of the SUSP/BODY rig with I1 = i1 at amplitude a (deg).
    real(dp) function period_of(i1, a) result(tp)
        real(dp), intent(in) :: i1, a
        type(deck_t) :: d
        type(status_t) :: st
        call read_deck_text(SCR//'/rig.nml', HEAD//SUSP//BODY, d, st)
        call torsion_period_s(rig_of(d), i1, a, tp, st)
        if (st%code /= 0) tp = -1.0_dp
    end function period_of

    !> Run a deck written here in-process; the value of key in its .identify (-1e300 when
    !! the run failed or the key is absent).
    real(dp) function kv(name, key) result(v)
        character(len=*), intent(in) :: name, key
        logical :: found
        call read_kv(SCR//'/'//name//'.identify', key, v, found)
        if (.not. found) v = -1.0e300_dp
    end function kv

    subroutine run_here(name, text, st)
        character(len=*), intent(in) :: name, text
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: line
        type(warning_t), allocatable :: w(:)
        call write_text(SCR//'/'//name//'.nml', text)
        call run_deck(SCR//'/'//name//'.nml', SCR, line, st, warnings=w)
    end subroutine run_here

    ! ---------------------------------------------------------------------------------------
    !> A semicolon table with decimal commas, a byte order mark, CR LF line ends, a quoted
    !! header; a table with text columns (its header required, its text kept).
    subroutine test_tables(t)
        type(tester_t), intent(inout) :: t
        type(table_t) :: tab
        type(status_t) :: st
        character(len=*), parameter :: CR = achar(13)
        call write_text(SCR//'/semi.csv', char(239)//char(187)//char(191)// &
            '"Time (s)";"Gyro Z (deg/s)"'//CR//NL//'0,00;1,5'//CR//NL//'0,01;-2,25e1'//CR//NL)
        call read_table(SCR//'/semi.csv', tab, st)
        call t%check('tables: semicolons, decimal commas, BOM, CR LF read', st%code == 0 .and. &
                     tab%nrow == 2 .and. tab%ncol == 2)
        if (st%code /= 0) return
        call t%check('tables: values', all(abs(tab%v(:, 2) - [1.5_dp, -22.5_dp]) < 1.0e-12_dp) &
                     .and. abs(tab%v(2, 1) - 0.01_dp) < 1.0e-15_dp)
        call t%check('tables: header names (quoted, lower case)', &
                     tab%column('gyro z (deg/s)') == 2 .and. tab%column('time (s)') == 1)
        call write_text(SCR//'/text.csv', 'trial, period, record'//NL//'A, 1.5, '//NL// &
            'B2, 1.6, swing b.csv'//NL)
        call read_table(SCR//'/text.csv', tab, st, text_columns=['trial ', 'record'])
        call t%check('tables: text columns kept', st%code == 0 .and. tab%nrow == 2)
        if (st%code /= 0) return
        call t%check('tables: text of the text columns, numbers of the others', &
                     tab%text(2, 1)%s == 'B2' .and. tab%text(2, 3)%s == 'swing b.csv' .and. &
                     tab%text(1, 3)%s == '' .and. abs(tab%v(2, 2) - 1.6_dp) < 1.0e-15_dp)
        call write_text(SCR//'/nohead.csv', '1, 1.5'//NL)
        call read_table(SCR//'/nohead.csv', tab, st, text_columns=['trial'])
        call t%check('tables: text columns need a header', st%code == 2 .and. &
                     index(st%msg, 'naming the columns') > 0)
    end subroutine test_tables

    ! ---------------------------------------------------------------------------------------
    !> Pooling: one release; consistent releases (the weighted mean, u_int, the
    !! Welch-Satterthwaite dof of their parts); releases that disagree (DerSimonian-Laird's
    !! between-release variance by hand, n - 1 dof, flagged); releases without their own u
    !! (the standard error of the mean); never below that standard error.
    subroutine test_pooling(t)
        type(tester_t), intent(inout) :: t
        type(pooled_t) :: p
        real(dp) :: x(4), u(4), w(4), q, t2, ws, m
        call pool_releases([2.0_dp], [0.1_dp], [5.0_dp], p)
        call t%check('pooling: one release is itself', p%mean == 2.0_dp .and. &
                     p%u_random == 0.1_dp .and. p%nu_random == 5.0_dp .and. &
                     p%consistency == 'single release')
        x = [10.0_dp, 10.1_dp, 9.95_dp, 10.05_dp]
        u = [0.1_dp, 0.1_dp, 0.2_dp, 0.1_dp]
        call pool_releases(x, u, [NU_INFINITE, NU_INFINITE, NU_INFINITE, NU_INFINITE], p)
        w = 1.0_dp/u**2
        call t%check_close('pooling: consistent, the weighted mean', p%mean, &
                           sum(w*x)/sum(w), rtol=1.0e-14_dp)
        call t%check_close('pooling: consistent, u = u_int', p%u_random, 1.0_dp/sqrt(sum(w)), &
                           rtol=1.0e-14_dp)
        call t%check('pooling: consistent, flagged so, dof infinite', &
                     p%consistency == 'consistent' .and. p%nu_random >= NU_INFINITE)
        call pool_releases(x, u, [4.0_dp, 4.0_dp, 4.0_dp, 4.0_dp], p)
        call t%check_close('pooling: consistent, Welch-Satterthwaite dof of the parts', &
                           p%nu_random, (1.0_dp/sum(w))**2/sum((w/sum(w)*u)**4/4.0_dp), &
                           rtol=1.0e-12_dp)
        x = [10.0_dp, 11.0_dp, 9.0_dp, 10.5_dp]
        u = 0.1_dp
        call pool_releases(x, u, [NU_INFINITE, NU_INFINITE, NU_INFINITE, NU_INFINITE], p)
        w = 1.0_dp/u**2
        ws = sum(w)
        m = sum(w*x)/ws
        q = sum(w*(x - m)**2)
        t2 = (q - 3.0_dp)/(ws - sum(w**2)/ws)
        call t%check('pooling: disagreeing releases flagged inconsistent', &
                     p%consistency == 'inconsistent' .and. p%p_value < 0.05_dp)
        call t%check_close('pooling: Birge ratio', p%birge, sqrt(q/3.0_dp), rtol=1.0e-12_dp)
        call t%check_close('pooling: between-release scatter tau^2 (DerSimonian-Laird)', &
                           p%tau**2, t2, rtol=1.0e-12_dp)
        call t%check('pooling: disagreeing, n - 1 dof and u >= the standard error of the mean', &
                     p%nu_random == 3.0_dp .and. p%u_random >= sqrt(sum((x - sum(x)/4)**2)/3/4) &
                     .and. p%u_reproducibility > 0.0_dp)
        call pool_releases(x, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], [1.0_dp, 1.0_dp, 1.0_dp, &
                           1.0_dp], p)
        call t%check_close('pooling: without u, the standard error of the mean', p%u_random, &
                           sqrt(sum((x - 10.125_dp)**2)/3.0_dp/4.0_dp), rtol=1.0e-12_dp)
        call t%check('pooling: without u, untested', p%consistency == 'not tested' .and. &
                     p%nu_random == 3.0_dp)
    end subroutine test_pooling

    ! ---------------------------------------------------------------------------------------
    !> The mistakes people make, each refused with one line on stderr naming the deck and
    !! the cause, and no file: g left out, the mass centre left out (exit 2); ten-cycle
    !! totals typed as periods, half spacings typed for b and b_prime, periods in ms (exit
    !! 4); a platform of three cables with another analysis than identify (exit 2); an I1
    !! just above I2 + I3 is a warning (exit 0, one line).
    subroutine test_traps(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: per
        real(dp) :: t1, t2
        t1 = period_of(I1_TRUE, 10.0_dp)
        t2 = period_of(I1_TRUE, 20.0_dp)
        per = '&measurement periods = '//num(t1)//', '//num(t2)//', amplitudes = 10, 20 /'//NL
        call one('nog', HEAD//'&suspension b = 0.4, b_prime = 0.4, l = 1.2, l_prime = 1.2 /'// &
                 NL//BODY//per, 2, 'not given: &suspension g')
        call one('nocg', HEAD//SUSP//'&body mass = 3.1, inertia = 0.0512, 0.063, 0.0304 /'// &
                 NL//per, 2, 'the mass centre')
        call one('totals', HEAD//SUSP//BODY//'&measurement periods = '//num(10*t1)//', '// &
                 num(10*t2)//', amplitudes = 10, 20 /'//NL, 4, 'cycles = N')
        call one('half_b', HEAD//'&suspension b = 0.2, b_prime = 0.2, l = 1.2, '// &
                 'l_prime = 1.2, g = 9.80665 /'//NL//BODY//per, 4, 'half the spacing')
        call one('mm', HEAD//SUSP//BODY//'&measurement periods = '//num(1000*t1)//', '// &
                 num(1000*t2)//', amplitudes = 10, 20 /'//NL, 4, 'units')
        call one('tri_sim', "&scene title = 'measure test', analyses = 'work_precision' /"// &
                 NL//'&suspension cables = 3, radius = 0.2, radius_prime = 0.15, l = 1.0, '// &
                 'g = 9.80665 /'//NL//'&body mass = 2.0, inertia = 0.04, 0.03, 0.03 /'//NL, 2, &
                 'not a platform of 3 cables')
        ! I1 5 % above I2 + I3: a warning, the number stands
        call fresh_dir(SCR//'/trap_lamina')
        t1 = period_of(1.05_dp*(0.063_dp + 0.0304_dp), 10.0_dp)
        call write_text(SCR//'/trap_lamina/l.nml', HEAD//SUSP//BODY//'&measurement '// &
                        'periods = '//num(t1)//', amplitudes = 10 /'//NL)
        call t%check('traps: I1 5 % above I2 + I3: exit 0, one warning line naming I2 + I3', &
                     all([run(exe//' '//SCR//'/trap_lamina/l.nml --out '//SCR//'/trap_lamina', &
                          SCR//'/trap_lamina') == 0, &
                          count_lines(SCR//'/trap_lamina/stderr') == 1, &
                          file_has(SCR//'/trap_lamina/stderr', 'warning'), &
                          file_has(SCR//'/trap_lamina/stderr', 'exceeds I2 + I3')]))
    contains
        subroutine one(name, text, code, word)
            character(len=*), intent(in) :: name, text, word
            integer, intent(in) :: code
            character(len=:), allocatable :: d
            integer :: ex
            d = SCR//'/trap_'//name
            call fresh_dir(d)
            call fresh_dir(d//'/out')
            call write_text(d//'/'//name//'.nml', text)
            ex = run(exe//' '//d//'/'//name//'.nml --out '//d//'/out', d)
            call t%check('traps: '//name//': exit '//itoa(code)//', one line naming the deck '// &
                         'and '''//word//''', no file', all([ex == code, &
                         count_lines(d//'/stderr') == 1, file_has(d//'/stderr', &
                         name//'.nml: '), file_has(d//'/stderr', word), &
                         count_lines(d//'/stdout') == 0, .not. file_has_any(d//'/out')]))
        end subroutine one
    end subroutine test_traps

    !> Whether a folder holds any file.
    logical function file_has_any(dir)
        character(len=*), intent(in) :: dir
        integer :: ex
        call execute_command_line('[ -z "$(ls -A '//dir//')" ]', exitstat=ex)
        file_has_any = ex /= 0
    end function file_has_any

    ! ---------------------------------------------------------------------------------------
    !> Timed totals of 10 cycles with cycles = 10 give the I1 of the periods themselves;
    !! their scatter is per timing (u_period_from_scatter of the totals); a tare and an added
    !! inertia are subtracted with their u; cg_depth, cg_offset give the I1 of the r, lambda
    !! they stand for, on a rig whose periods are simulated (unequal cables).
    subroutine test_decks(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        real(dp) :: t1, t2, t3, i_per, i_tot, u_tot, u_b, r, lam
        character(len=:), allocatable :: asym
        t1 = period_of(I1_TRUE, 10.0_dp)
        t2 = period_of(I1_TRUE, 10.0_dp)
        t3 = period_of(I1_TRUE, 10.0_dp)
        call run_here('per', HEAD//SUSP//BODY//'&measurement periods = '//num(t1)//', '// &
                      num(t2 + 1.0e-3_dp)//', '//num(t3 - 2.0e-3_dp)//', amplitudes = 10, 10, 10 /'// &
                      NL, st)
        call t%check('cycles: periods deck runs', st%code == 0)
        call run_here('tot', HEAD//SUSP//BODY//'&measurement periods = '//num(10*t1)//', '// &
                      num(10*t2 + 1.0e-2_dp)//', '//num(10*t3 - 2.0e-2_dp)//', cycles = 10, '// &
                      'amplitudes = 10, 10, 10 /'//NL, st)
        call t%check('cycles: totals of 10 cycles run', st%code == 0)
        call t%check_close('cycles: the same I1 from totals of 10 cycles', kv('tot', 'I1'), &
                           kv('per', 'I1'), rtol=1.0e-12_dp)
        call t%check_close('cycles: the timing scatter is the totals''', &
                           kv('tot', 'u_period_from_scatter'), &
                           10*kv('per', 'u_period_from_scatter'), rtol=1.0e-9_dp)
        call t%check_close('cycles: the same u_I1 (errors per timing 10 times those per '// &
                           'cycle)', kv('tot', 'u_I1'), kv('per', 'u_I1'), rtol=1.0e-6_dp)
        call t%check_close('cycles: dof_eff n - 1 = 2 (the scatter of three timings)', &
                           kv('tot', 'dof_eff'), 2.0_dp, rtol=1.0e-9_dp)
        call t%check_close('cycles: k = t(0.975, 2) = 4.303', kv('tot', 'k'), 4.30265273_dp, &
                           rtol=1.0e-7_dp)
        ! two timings at one amplitude that disagree, the amplitude uncertain: Gauss-Newton
        ! ends at the optimum (its line search at roundoff is convergence, not exit 3)
        call run_here('gn', HEAD//SUSP//BODY//'&measurement periods = '//num(10*t1 - 0.03_dp)// &
                      ', '//num(10*t1 + 0.02_dp)//', cycles = 10, amplitudes = 10, 10, '// &
                      'u_period = 0.05, u_amplitude = 1 /'//NL, st)
        call t%check('equal amplitudes, scattered timings, u_amplitude: converges (exit 0)', &
                     st%code == 0)
        call t%check_close('... to the I1 of the mean period', kv('gn', 'I1'), &
                           I1_TRUE*(1.0_dp - 0.005_dp/(10*t1))**2, rtol=2.0e-4_dp)
        ! a tare and an added inertia
        call run_here('tare', HEAD//SUSP//BODY//'&measurement periods = '//num(t1)//', '// &
                      'amplitudes = 10, u_period = 1e-4, u_b = 5e-4, tare_I1 = 0.004, '// &
                      'u_tare_I1 = 1e-4, tare_mass = 0.3, added_inertia = 0.0005, '// &
                      'u_added_inertia = 5e-5 /'//NL, st)
        call t%check('tare: runs', st%code == 0)
        i_per = kv('tare', 'I1')
        i_tot = kv('tare', 'I1_total')
        u_tot = kv('tare', 'u_I1_total')
        call t%check_close('tare: I1_total is the rig''s I1', i_tot, I1_TRUE, rtol=1.0e-9_dp)
        call t%check_close('tare: I1 = I1_total - tare_I1 - added_inertia', i_per, &
                           i_tot - 0.004_dp - 0.0005_dp, rtol=1.0e-13_dp)
        call t%check_close('tare: u_I1^2 = u_I1_total^2 + u_tare^2 + u_added^2', &
                           kv('tare', 'u_I1'), sqrt(u_tot**2 + 1.0e-8_dp + 2.5e-9_dp), &
                           rtol=1.0e-12_dp)
        u_b = I1_TRUE/0.4_dp*5.0e-4_dp
        call t%check('tare: u_I1_total holds the period''s and b''s parts', u_tot > u_b .and. &
                     u_tot < 2*u_b + 1.0e-4_dp*2*I1_TRUE/t1)
        call t%check_close('tare: mass_body = mass - tare_mass', kv('tare', 'mass_body'), &
                           2.8_dp, rtol=1.0e-14_dp)
        ! cg_depth, cg_offset against r, lambda on unequal cables (simulated periods)
        r = sqrt((0.2_dp + 0.03_dp)**2 + 0.15_dp**2)
        lam = atan2(0.15_dp, 0.2_dp + 0.03_dp)
        asym = '&suspension b = 0.4, b_prime = 0.4, l = 1.2, l_prime = 1.17, g = 9.80665 /'//NL
        call run_here('cgd', HEAD//asym//'&body mass = 3.1, inertia = 0.05, 0.063, 0.0304, '// &
                      'cg_depth = 0.15, cg_offset = 0.03 /'//NL//'&measurement periods = '// &
                      '1.43, amplitudes = 20 /'//NL, st)
        call t%check('cg_depth: runs (simulated periods)', st%code == 0)
        call run_here('rl', HEAD//asym//'&body mass = 3.1, inertia = 0.05, 0.063, 0.0304, '// &
                      'r = '//num(r)//', lambda = '//num(lam)//' /'//NL//'&measurement '// &
                      'periods = 1.43, amplitudes = 20 /'//NL, st)
        call t%check_close('cg_depth: the I1 of r and lambda', kv('cgd', 'I1'), kv('rl', 'I1'), &
                           rtol=1.0e-9_dp)
        ! r, lambda typed to 8 digits on a symmetric rig: symmetric (to 1e-6), exact torsion
        call run_here('rl8', HEAD//SUSP//'&body mass = 3.1, inertia = 0.0512, 0.063, 0.0304, '// &
                      'r = 0.25, lambda = 0.64350111 /'//NL//'&measurement periods = '// &
                      num(t1)//', amplitudes = 10 /'//NL, st)
        call t%check('r, lambda to 8 digits: exact torsion', all([st%code == 0, &
                     file_has(SCR//'/rl8.identify', 'period_model = exact torsion')]))
    end subroutine test_decks

    ! ---------------------------------------------------------------------------------------
    !> A trifilar platform (three cables at radius R on the support, R' on the body, length
    !! l): its exact torsion period computed here from the energy integral,
    !! z(theta) = (l^2 - R^2 - R'^2 + 2 R R' cos theta)^(1/2), T = 4 int_0^A ((I1 +
    !! m z'^2)/(2 m g (z - z(A))))^(1/2) dtheta (theta = A sin phi, the midpoint rule on
    !! 20000 intervals); identify with cables = 3 recovers I1 from two such periods.
    subroutine test_trifilar(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        real(dp), parameter :: R = 0.2_dp, RP = 0.15_dp, L = 1.0_dp, M = 2.0_dp, G = 9.80665_dp
        real(dp), parameter :: I1 = 0.0412_dp
        real(dp) :: t1, t2
        t1 = tri_period(5.0_dp*deg)
        t2 = tri_period(40.0_dp*deg)
        call run_here('tri', HEAD//'&suspension cables = 3, radius = 0.2, radius_prime = 0.15, '// &
                      'l = 1.0, g = 9.80665 /'//NL//'&body mass = 2.0, inertia = 0.04, 0.03, '// &
                      '0.03 /'//NL//'&measurement periods = '//num(t1)//', '//num(t2)// &
                      ', amplitudes = 5, 40 /'//NL, st)
        call t%check('trifilar: runs', st%code == 0)
        call t%check_close('trifilar: I1 of the independent quadrature', kv('tri', 'I1'), I1, &
                           rtol=1.0e-8_dp)
        call t%check('trifilar: exact torsion', file_has(SCR//'/tri.identify', &
                     'period_model = exact torsion'))
        ! the cables' one length in the budget: its sensitivity that of moving every cable
        call run_here('tri_u', HEAD//'&suspension cables = 3, radius = 0.2, radius_prime = '// &
                      '0.15, l = 1.0, g = 9.80665 /'//NL//'&body mass = 2.0, inertia = 0.04, '// &
                      '0.03, 0.03 /'//NL//'&measurement periods = '//num(t1)//', '//num(t2)// &
                      ', amplitudes = 5, 40, u_l = 0.001 /'//NL, st)
        call run_here('tri_p', HEAD//'&suspension cables = 3, radius = 0.2, radius_prime = '// &
                      '0.15, l = 1.0001, g = 9.80665 /'//NL//'&body mass = 2.0, inertia = 0.04, '// &
                      '0.03, 0.03 /'//NL//'&measurement periods = '//num(t1)//', '//num(t2)// &
                      ', amplitudes = 5, 40 /'//NL, st)
        call run_here('tri_m', HEAD//'&suspension cables = 3, radius = 0.2, radius_prime = '// &
                      '0.15, l = 0.9999, g = 9.80665 /'//NL//'&body mass = 2.0, inertia = 0.04, '// &
                      '0.03, 0.03 /'//NL//'&measurement periods = '//num(t1)//', '//num(t2)// &
                      ', amplitudes = 5, 40 /'//NL, st)
        call t%check_close('trifilar: the budget''s length row moves every cable', &
                           row_sensitivity(SCR//'/tri_u.identify', 'length'), &
                           (kv('tri_p', 'I1') - kv('tri_m', 'I1'))/2.0e-4_dp, rtol=1.0e-5_dp)
    contains
        real(dp) function tri_period(a) result(tp)
            real(dp), intent(in) :: a
            integer, parameter :: N = 20000
            real(dp) :: phi, th, z, za, dz, dzdt, s
            integer :: k
            za = sqrt(L**2 - R**2 - RP**2 + 2*R*RP*cos(a))
            s = 0.0_dp
            do k = 1, N
                phi = (k - 0.5_dp)*0.5_dp*pi/N
                th = a*sin(phi)
                z = sqrt(L**2 - R**2 - RP**2 + 2*R*RP*cos(th))
                ! z - z(A) = 2 R R' (cos th - cos A)/(z + z(A)), without cancellation
                dz = 4*R*RP*sin(0.5_dp*(a + th))*sin(0.5_dp*(a - th))/(z + za)
                dzdt = -R*RP*sin(th)/z
                s = s + sqrt((I1 + M*dzdt**2)/(2*M*G*dz))*a*cos(phi)
            end do
            tp = 4*s*0.5_dp*pi/N
        end function tri_period
    end subroutine test_trifilar

    ! ---------------------------------------------------------------------------------------
    !> A phone's gyro export: a CSV with a header, five columns (time, three accelerations
    !! and the gyro's z in deg/s), a bias of 0.6 deg/s, noise 0.3 deg/s at 100 Hz, the body
    !! held for 1.4 s and then released (times from 0 at the start of the record).  With
    !! record_columns = 1, 5, record_units = 'deg/s' and estimate = 'I1 c_v amplitude t0
    !! bias': I1 within 0.1 %, c_v and the bias within 3 u, the release within 0.02 s.
    !! Without bias estimated: a warning line naming the bias.
    subroutine test_phone(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(deck_t) :: d
        type(status_t) :: st
        type(rng_t) :: g
        real(dp), parameter :: CV = 2.0e-3_dp, BIAS = 0.6_dp, NOISE = 0.3_dp, T0 = 1.4_dp
        real(dp), allocatable :: tt(:), w(:)
        character(len=:), allocatable :: text, rigtext, csv
        character(len=120) :: row
        integer :: i, n, ex
        real(dp) :: cv_fit, ucv
        rigtext = HEAD//'&suspension b = 0.4, b_prime = 0.4, l = 1.2, l_prime = 1.18, '// &
            'g = 9.80665 /'//NL//'&body mass = 3.1, inertia = 0.0512, 0.063, 0.0304, '// &
            'cg_depth = 0.15, cg_offset = 0.02 /'//NL//"&start mode = 'raised', "// &
            'amplitude = 25 /'//NL
        call read_deck_text(SCR//'/phone_truth.nml', rigtext//'&damping c_v = '//num(CV)// &
                            ' /'//NL//'&integration rtol = 1e-12, atol = 1e-14 /'//NL, d, st)
        call t%check('phone: the truth deck reads', st%code == 0)
        if (st%code /= 0) return
        n = 2001
        allocate (tt(n), w(n))
        do i = 1, n
            tt(i) = (i - 1)*0.01_dp
        end do
        call record_model(rig_of(d), start_of(d), accuracy_of(d), tt, T0, .true., w, st)
        call t%check('phone: the truth record', st%code == 0)
        if (st%code /= 0) return
        g = rng_stream(77, 0)
        csv = '"Time (s)","Acceleration x (m/s^2)","Acceleration y (m/s^2)",'// &
              '"Acceleration z (m/s^2)","Gyroscope z (deg/s)"'//NL
        do i = 1, n
            write (row, '(f0.3,3(a,f0.4),a,f0.5)') tt(i), ',', 0.01_dp*rng_normal(g), ',', &
                9.81_dp + 0.01_dp*rng_normal(g), ',', 0.01_dp*rng_normal(g), ',', &
                w(i)/deg + BIAS + NOISE*rng_normal(g)
            csv = csv//trim(row)//NL
        end do
        call write_text(SCR//'/phone.csv', csv)
        text = rigtext//"&measurement record = 'phone.csv', record_columns = 1, 5, "// &
            "record_units = 'deg/s', estimate = 'I1 c_v amplitude t0 bias' /"//NL
        call run_here('phone', text, st)
        call t%check('phone: the fit converges (exit 0)', st%code == 0)
        if (st%code /= 0) then
            write (*, '(a)') '   '//st%msg
            return
        end if
        call t%check_close('phone: I1 within 0.1 %', kv('phone', 'I1'), I1_TRUE, rtol=1.0e-3_dp)
        cv_fit = kv('phone', 'c_v')
        ucv = kv('phone', 'u_c_v')
        call t%check('phone: c_v within 3 u of the truth ('//trim(num(cv_fit))//' +- '// &
                     trim(num(ucv))//')', abs(cv_fit - CV) <= 3*ucv .and. ucv < 0.5_dp*CV)
        call t%check('phone: bias within 3 u (rad/s)', abs(kv('phone', 'bias') - BIAS*deg) <= &
                     3*kv('phone', 'u_bias'))
        call t%check('phone: release found within 0.02 s', abs(kv('phone', 't0') - T0) < 0.02_dp)
        call t%check('phone: the fit figure''s data in deg/s', file_has(SCR//'/phone.fit.dat', &
                     'W (deg/s)'))
        ! the same record, the bias not estimated: a warning names it
        call fresh_dir(SCR//'/phone_nobias')
        call execute_command_line('cp '//SCR//'/phone.csv '//SCR//'/phone_nobias/')
        call write_text(SCR//'/phone_nobias/nb.nml', rigtext//"&measurement record = "// &
                        "'phone.csv', record_columns = 1, 5, record_units = 'deg/s', "// &
                        "estimate = 'I1 c_v amplitude t0' /"//NL)
        ex = run(exe//' '//SCR//'/phone_nobias/nb.nml --out '//SCR//'/phone_nobias', &
                 SCR//'/phone_nobias')
        call t%check('phone: without bias estimated, exit 0 and a warning naming the bias', &
                     all([ex == 0, count_lines(SCR//'/phone_nobias/stderr', 'warning') == 1, &
                          file_has(SCR//'/phone_nobias/stderr', 'add bias to')]))
    end subroutine test_phone

    ! ---------------------------------------------------------------------------------------
    !> A table of releases: three releases that agree (consistent, no warning), then five
    !! whose I1 differ by 2 % with timings good to 1 ms (inconsistent: one warning line,
    !! exit 0, the key in the file, u at least the standard error of their mean); a table
    !! with a misspelt column and one whose release changes its rig are refused (exit 2).
    subroutine test_trials(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: tab, dd
        real(dp) :: i1s(5), sem, m
        integer :: r, k, ex
        character(len=32) :: val
        dd = SCR//'/trials'
        call fresh_dir(dd)
        tab = 'trial,period,cycles,amplitude'//NL
        do r = 1, 3
            do k = 1, 2
                tab = tab//itoa(r)//','//num(10*period_of(I1_TRUE, 10.0_dp) + &
                      1.0e-3_dp*(-1)**(r + k))//',10,10'//NL
            end do
        end do
        call write_text(dd//'/ok.csv', tab)
        call write_text(dd//'/ok.nml', HEAD//SUSP//BODY//"&measurement trials = 'ok.csv', "// &
                        'u_period = 0.002 /'//NL)
        ex = run(exe//' '//dd//'/ok.nml --out '//dd, dd)
        call read_kv_text(dd//'/ok.identify', 'consistency', val)
        call t%check('trials: three agreeing releases: consistent, no warning', all([ex == 0, &
                     trim(val) == 'consistent', count_lines(dd//'/stderr') == 0]))
        i1s = I1_TRUE*[1.0_dp, 1.02_dp, 0.98_dp, 1.01_dp, 0.99_dp]
        tab = 'trial,period,cycles,amplitude,u_period'//NL
        do r = 1, 5
            tab = tab//'r'//itoa(r)//','//num(10*period_of(i1s(r), 10.0_dp))//',10,10,0.001'//NL
        end do
        call write_text(dd//'/bad.csv', tab)
        call write_text(dd//'/bad.nml', HEAD//SUSP//BODY//"&measurement trials = 'bad.csv' /"//NL)
        ex = run(exe//' '//dd//'/bad.nml --out '//dd, dd)
        call read_kv_text(dd//'/bad.identify', 'consistency', val)
        call t%check('trials: disagreeing releases: exit 0, inconsistent in the file', &
                     ex == 0 .and. trim(val) == 'inconsistent')
        call t%check('trials: disagreeing releases: one warning line', &
                     all([count_lines(dd//'/stderr') == 1, file_has(dd//'/stderr', &
                          'releases disagree')]))
        m = sum(i1s)/5
        sem = sqrt(sum((i1s - m)**2)/4/5)
        call t%check('trials: u_I1 at least the standard error of the releases'' mean', &
                     kvp(dd//'/bad.identify', 'u_I1') >= 0.999_dp*sem)
        call t%check_close('trials: k from 4 dof (t = 2.776)', kvp(dd//'/bad.identify', 'k'), &
                           2.77644511_dp, rtol=1.0e-6_dp)
        call t%check('trials: five releases counted', &
                     nint(kvp(dd//'/bad.identify', 'n_trials')) == 5)
        call write_text(dd//'/typo.csv', 'trial,perod'//NL//'1,1.5'//NL)
        call write_text(dd//'/typo.nml', HEAD//SUSP//BODY//"&measurement trials = 'typo.csv' /"// &
                        NL)
        ex = run(exe//' '//dd//'/typo.nml --out '//dd, dd)
        call t%check('trials: a misspelt column refused, one line naming it', all([ex == 2, &
                     count_lines(dd//'/stderr') == 1, file_has(dd//'/stderr', '''perod''')]))
        call write_text(dd//'/mix.csv', 'trial,period,amplitude,record'//NL//'1,1.45,10,'//NL// &
                        '2,0,10,swing.csv'//NL)
        call write_text(dd//'/mix.nml', HEAD//SUSP//BODY//"&measurement trials = 'mix.csv' /"//NL)
        ex = run(exe//' '//dd//'/mix.nml --out '//dd, dd)
        call t%check('trials: periods and records in one table refused, one line', &
                     all([ex == 2, count_lines(dd//'/stderr') == 1, &
                          file_has(dd//'/stderr', 'one kind of release per table')]))
        call write_text(dd//'/rig.csv', 'trial,l,period,amplitude'//NL//'1,1.2,1.5,10'//NL//'1,1.3,1.5,10'//NL)
        call write_text(dd//'/rig.nml', HEAD//SUSP//BODY//"&measurement trials = 'rig.csv' /"//NL)
        ex = run(exe//' '//dd//'/rig.nml --out '//dd, dd)
        call t%check('trials: a release whose rig changes refused (line 3, column l)', &
                     all([ex == 2, count_lines(dd//'/stderr') == 1, &
                          file_has(dd//'/stderr', 'line 3, column l = ')]))
    end subroutine test_trials

    ! ---------------------------------------------------------------------------------------
    !> The one measurement model: a table of record releases where one release estimates
    !! fewer parameters (its column estimate) runs with each release's own; a release that
    !! fails stops the run (exit 4, named with its row), or with on_failure = 'skip' is left
    !! out, named on one warning line, counted in n_trials_skipped; a column session is
    !! carried into NAME.identify, and &measurement session for the deck's one release; the
    !! one table reader gives the same message for the same fault in a table of releases and
    !! in a table of hangs (a column twice, an unknown column, a value out of range).
    subroutine test_model(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(deck_t) :: d
        type(status_t) :: st
        type(measurement_t) :: m
        type(rng_t) :: g
        real(dp), parameter :: CV = 2.0e-3_dp
        real(dp), allocatable :: tt(:), th(:)
        character(len=:), allocatable :: dd, rigtext, tab, s1
        character(len=64) :: row
        character(len=32) :: val
        integer :: i, n, k, ex
        dd = SCR//'/model'
        call fresh_dir(dd)
        ! --- a release that estimates fewer parameters: its own estimate
        rigtext = HEAD//SUSP//BODY//"&start mode = 'raised', amplitude = 20 /"//NL
        n = 401
        allocate (tt(n), th(n))
        do i = 1, n
            tt(i) = (i - 1)*0.02_dp
        end do
        g = rng_stream(31, 0)
        do k = 1, 2
            call read_deck_text(dd//'/truth.nml', rigtext//'&damping c_v = '// &
                                num(merge(CV, 0.0_dp, k == 1))//' /'//NL// &
                                '&integration rtol = 1e-12, atol = 1e-14 /'//NL, d, st)
            if (st%code == 0) call record_model(rig_of(d), start_of(d), accuracy_of(d), tt, &
                                                0.0_dp, .false., th, st)
            call t%check('model: truth record '//itoa(k), st%code == 0)
            if (st%code /= 0) return
            tab = '# t theta4'//NL
            do i = 1, n
                write (row, '(f0.3,1x,es16.8)') tt(i), th(i) + 1.0e-4_dp*rng_normal(g)
                tab = tab//trim(row)//NL
            end do
            call write_text(dd//'/'//achar(iachar('a') + k - 1)//'.dat', tab)
        end do
        call write_text(dd//'/rec.csv', 'trial,record,estimate'//NL//'A,a.dat,'//NL// &
                        'B,b.dat,I1'//NL)
        call write_text(dd//'/rec.nml', rigtext//"&measurement trials = 'rec.csv', "// &
                        "estimate = 'I1 c_v' /"//NL)
        call read_deck_text(dd//'/rec.nml', rigtext//"&measurement trials = 'rec.csv', "// &
                            "estimate = 'I1 c_v' /"//NL, d, st)
        if (st%code == 0) call read_releases(d%measurement, rig_of(d), start_of(d), &
                                             d%suspension%cables, deck_inputs(d, .true.), m, st)
        call t%check('model: per-release estimate read (A the deck''s, B its own)', &
                     st%code == 0 .and. size(m%releases) == 2)
        if (st%code /= 0) return
        call t%check('model: ... A estimates I1 c_v, B I1 alone', &
                     m%releases(1)%estimate == 'I1 c_v' .and. m%releases(2)%estimate == 'I1')
        ex = run(exe//' '//dd//'/rec.nml --out '//dd, dd)
        call t%check('model: a table with one release that needs fewer parameters runs '// &
                     '(exit 0)', ex == 0)
        call t%check('model: ... two releases pooled, I1 within 0.5 %', &
                     all([nint(kvp(dd//'/rec.identify', 'n_trials')) == 2, &
                          abs(kvp(dd//'/rec.identify', 'I1')/I1_TRUE - 1.0_dp) < 5.0e-3_dp]))
        call t%check('model: ... c_v from the release that estimates it, within 3 u', &
                     abs(kvp(dd//'/rec.identify', 'c_v') - CV) <= &
                     3*kvp(dd//'/rec.identify', 'u_c_v'))
        ! --- a release that fails: stop (the default), or left out with on_failure = 'skip'
        tab = 'trial,period,cycles,amplitude,u_period'//NL
        do k = 1, 2
            tab = tab//'r'//itoa(k)//','//num(10*period_of(I1_TRUE, 10.0_dp))//',10,10,0.001'//NL
        end do
        tab = tab//'bad,'//num(1.0e4_dp*period_of(I1_TRUE, 10.0_dp))//',10,10,0.001'//NL
        call write_text(dd//'/skip.csv', tab)
        call write_text(dd//'/stop.nml', HEAD//SUSP//BODY//"&measurement trials = 'skip.csv' /"//NL)
        ex = run(exe//' '//dd//'/stop.nml --out '//dd, dd)
        call t%check('model: a release that fails stops the run (exit 4), one line naming '// &
                     'its row', all([ex == 4, count_lines(dd//'/stderr') == 1, &
                     file_has(dd//'/stderr', 'trial ''bad'' (line 4)')]))
        call write_text(dd//'/skip.nml', HEAD//SUSP//BODY//"&measurement trials = 'skip.csv', "// &
                        "on_failure = 'skip' /"//NL)
        ex = run(exe//' '//dd//'/skip.nml --out '//dd, dd)
        call t%check('model: on_failure = ''skip'': exit 0, one warning naming the release '// &
                     'and its row', all([ex == 0, count_lines(dd//'/stderr', 'warning') == 1, &
                     file_has(dd//'/stderr', 'trial ''bad'' (line 4)'), &
                     file_has(dd//'/stderr', 'on_failure')]))
        call t%check('model: ... n_trials = 2, n_trials_skipped = 1', &
                     all(nint([kvp(dd//'/skip.identify', 'n_trials'), &
                               kvp(dd//'/skip.identify', 'n_trials_skipped')]) == [2, 1]))
        call read_kv_text(dd//'/skip.identify', 'trial_skipped(1)', val)
        call t%check('model: ... trial_skipped(1) names it: '//trim(val), &
                     index(val, 'trial ''bad'' (line 4)') > 0)
        ! --- sessions: a column session, and the deck's one release's
        tab = 'trial,session,period,cycles,amplitude,u_period'//NL
        do k = 1, 3
            tab = tab//'r'//itoa(k)//','//trim(merge('mon', 'tue', k < 3))//','// &
                num(10*period_of(I1_TRUE, 10.0_dp) + 1.0e-3_dp*k)//',10,10,0.002'//NL
        end do
        call write_text(dd//'/sess.csv', tab)
        call write_text(dd//'/sess.nml', HEAD//SUSP//BODY//"&measurement trials = 'sess.csv' /"//NL)
        ex = run(exe//' '//dd//'/sess.nml --out '//dd, dd)
        call read_kv_text(dd//'/sess.identify', 'session(1)', val)
        s1 = trim(val)
        call read_kv_text(dd//'/sess.identify', 'session(3)', val)
        call t%check('model: a column session carried to NAME.identify (session(1) = mon, '// &
                     'session(3) = tue)', ex == 0 .and. s1 == 'mon' .and. trim(val) == 'tue')
        call write_text(dd//'/one.nml', HEAD//SUSP//BODY//'&measurement periods = '// &
                        num(period_of(I1_TRUE, 10.0_dp))//", amplitudes = 10, u_period = 1e-4, "// &
                        "session = 'lab 3' /"//NL)
        ex = run(exe//' '//dd//'/one.nml --out '//dd, dd)
        call read_kv_text(dd//'/one.identify', 'session', val)
        call t%check('model: &measurement session of the deck''s release written', &
                     ex == 0 .and. trim(val) == 'lab 3')
        ! --- the one table reader: the same messages in both tables
        call write_text(dd//'/rt_twice.csv', 'trial,period,period'//NL//'1,1.5,1.5'//NL)
        call write_text(dd//'/ht_twice.csv', 'hang up_x up_y up_z along_x along_y along_z '// &
                        'period period'//NL//'1 1 0 0 0 1 0 1.5 1.5'//NL)
        call both('twice', 'column ''period'' appears twice; allowed: each column once')
        call write_text(dd//'/rt_unknown.csv', 'trial,perod'//NL//'1,1.5'//NL)
        call write_text(dd//'/ht_unknown.csv', 'hang up_x up_y up_z along_x along_y along_z '// &
                        'perod'//NL//'1 1 0 0 0 1 0 1.5'//NL)
        call both('unknown', 'unknown column ''perod'' (column ')
        call write_text(dd//'/rt_value.csv', 'trial,period,cycles'//NL//'1,1.5,0.1'//NL)
        call write_text(dd//'/ht_value.csv', 'hang up_x up_y up_z along_x along_y along_z '// &
                        'period cycles'//NL//'1 1 0 0 0 1 0 1.5 0.1'//NL)
        call both('value', 'line 2, column cycles = 0.1; allowed: ')
    contains
        !> The fault `what` in a table of releases and in a table of hangs: both refused, each
        !! message one line naming its table and holding `word`.
        subroutine both(what, word)
            character(len=*), intent(in) :: what, word
            type(deck_t) :: dr, dh
            type(status_t) :: sr, sh
            type(measurement_t) :: mr, mh
            call read_deck_text(dd//'/rt.nml', HEAD//SUSP//BODY//"&measurement trials = "// &
                                "'rt_"//what//".csv' /"//NL, dr, sr)
            if (sr%code == 0) call read_releases(dr%measurement, rig_of(dr), start_of(dr), &
                dr%suspension%cables, deck_inputs(dr, .true.), mr, sr)
            call read_deck_text(dd//'/ht.nml', "&scene analyses = 'tensor' /"//NL//SUSP// &
                                '&body mass = 3.1, inertia = 0.05, 0.06, 0.07, cg_depth = '// &
                                '0.1, cg_offset = 0 /'//NL//"&tensor hangs = 'ht_"//what// &
                                ".csv' /"//NL, dh, sh)
            if (sh%code == 0) call read_hangs(dh%tensor, dh%suspension, dh%body, mh, sh)
            call t%check('model: one reader, '//what//': the table of releases: '//sr%msg, &
                         sr%code == 2 .and. index(sr%msg, word) > 0 .and. &
                         index(sr%msg, '&measurement trials = ''rt_'//what//'.csv'': ') == 1)
            call t%check('model: one reader, '//what//': the table of hangs: '//sh%msg, &
                         sh%code == 2 .and. index(sh%msg, word) > 0 .and. &
                         index(sh%msg, '&tensor hangs = ''ht_'//what//'.csv'': ') == 1)
        end subroutine both
    end subroutine test_model

    real(dp) function kvp(path, key) result(v)
        character(len=*), intent(in) :: path, key
        logical :: found
        call read_kv(path, key, v, found)
        if (.not. found) v = -1.0e300_dp
    end function kvp

    ! ---------------------------------------------------------------------------------------
    !> Over 20 seeds: five releases, each timed three times over 10 cycles (timing u 0.01 s
    !! stated), each release's I1 off by a normal 1.5 % (what changes between releases: the
    !! hang, the start, the air), the table pooled.  The 95 % interval I1 +- U covers the
    !! truth in at least 17 of 20 (binomial at 0.95: 98 %); the releases' own u alone (u_int,
    !! k = 2) would cover it in few.
    subroutine test_coverage(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st
        type(rng_t) :: g
        character(len=:), allocatable :: tab, name
        real(dp) :: i1r, big_u, i1, tp
        integer :: seed, r, k, inside, ok, naive
        inside = 0
        ok = 0
        naive = 0
        name = ''
        do seed = 1, 20
            g = rng_stream(1000 + seed, 0)
            tab = 'trial,period,cycles,amplitude,u_period'//NL
            do r = 1, 5
                i1r = I1_TRUE*(1.0_dp + 0.015_dp*rng_normal(g))
                tp = period_of(i1r, 10.0_dp)
                do k = 1, 3
                    tab = tab//itoa(r)//','//num(10*tp + 0.01_dp*rng_normal(g))//',10,10,0.01'//NL
                end do
            end do
            name = 'cov'//itoa(seed)
            call write_text(SCR//'/'//name//'.csv', tab)
            call run_here(name, HEAD//SUSP//BODY//"&measurement trials = '"//name//".csv' /"// &
                          NL, st)
            if (st%code /= 0) then
                write (*, '(a)') '   seed '//itoa(seed)//': '//st%msg
                cycle
            end if
            ok = ok + 1
            i1 = kv(name, 'I1')
            big_u = kv(name, 'U_I1')
            if (abs(i1 - I1_TRUE) <= big_u) inside = inside + 1
            if (abs(i1 - I1_TRUE) <= 2*(kv(name, 'u_I1')**2 - &
                kv(name, 'u_I1_reproducibility')**2)**0.5_dp) naive = naive + 1
        end do
        write (*, '(a)') '   coverage over releases: '//itoa(inside)//' of 20 within U; '// &
            'the releases'' own u would cover '//itoa(naive)
        call t%check('coverage: 20 pooled tables run', ok == 20)
        call t%check('coverage: I1 +- U covers the truth in at least 17 of 20', inside >= 17)
        call t%check('coverage: the releases'' own u alone would not', naive < 12)
    end subroutine test_coverage

    ! ---------------------------------------------------------------------------------------
    !> Over 20 seeds: 3 sessions of 3 releases, each session's I1 off by a normal 2 % (what
    !! a session shares: the hanging, the day), each release's by a further 0.5 %, each
    !! release timed once over 10 cycles (timing u 0.01 s stated).  Pooled in two levels
    !! (the column session) the 95 % interval I1 +- U covers the truth in at least 17 of 20;
    !! the same table without the column (one level: nine releases as one population)
    !! covers it in fewer.  Both counts are printed.  One table's budget has the row
    !! u_I1_session, n_sessions = 3 and I1_session(i) with u.
    subroutine test_sessions(t)
        type(tester_t), intent(inout) :: t
        type(status_t) :: st, st1
        type(rng_t) :: g
        character(len=:), allocatable :: tab, tab1, name
        character(len=2) :: lab
        real(dp) :: i1s, i1r, tp
        integer :: seed, s, r, two, one, ok
        two = 0
        one = 0
        ok = 0
        name = ''
        do seed = 1, 20
            g = rng_stream(2000 + seed, 0)
            tab = 'trial,session,period,cycles,amplitude,u_period'//NL
            tab1 = 'trial,period,cycles,amplitude,u_period'//NL
            do s = 1, 3
                i1s = I1_TRUE*(1.0_dp + 0.02_dp*rng_normal(g))
                lab = 's'//itoa(s)
                do r = 1, 3
                    i1r = i1s*(1.0_dp + 0.005_dp*rng_normal(g))
                    tp = 10*period_of(i1r, 10.0_dp) + 0.01_dp*rng_normal(g)
                    tab = tab//lab//'r'//itoa(r)//','//lab//','//num(tp)//',10,10,0.01'//NL
                    tab1 = tab1//lab//'r'//itoa(r)//','//num(tp)//',10,10,0.01'//NL
                end do
            end do
            name = 'ses'//itoa(seed)
            call write_text(SCR//'/'//name//'.csv', tab)
            call write_text(SCR//'/'//name//'_1.csv', tab1)
            call run_here(name, HEAD//SUSP//BODY//"&measurement trials = '"//name//".csv' /"// &
                          NL, st)
            call run_here(name//'_1', HEAD//SUSP//BODY//"&measurement trials = '"//name// &
                          "_1.csv' /"//NL, st1)
            if (st%code /= 0 .or. st1%code /= 0) then
                write (*, '(a)') '   seed '//itoa(seed)//': '//st%msg//' '//st1%msg
                cycle
            end if
            ok = ok + 1
            if (abs(kv(name, 'I1') - I1_TRUE) <= kv(name, 'U_I1')) two = two + 1
            if (abs(kv(name//'_1', 'I1') - I1_TRUE) <= kv(name//'_1', 'U_I1')) one = one + 1
        end do
        write (*, '(a)') '   sessions: two-level pooling covers the truth in '//itoa(two)// &
            ' of 20, one-level pooling in '//itoa(one)//' of 20'
        call t%check('sessions: 40 pooled tables run', ok == 20)
        call t%check('sessions: two levels: I1 +- U covers the truth in at least 17 of 20', &
                     two >= 17)
        call t%check('sessions: one level covers it in fewer', one < two)
        call t%check('sessions: n_sessions = 3, I1_session(3) with u, k from few dof', &
                     all([nint(kv('ses1', 'n_sessions')) == 3, kv('ses1', 'I1_session(3)') > 0, &
                          kv('ses1', 'u_I1_session(3)') > 0, kv('ses1', 'k') > 2.5_dp]))
        call t%check('sessions: the budget has the row u_I1_session', &
                     all([file_has(SCR//'/ses1.identify', 'u_I1_session  '), &
                          kv('ses1', 'u_I1_session') > 0]))
        call t%check('sessions: one level writes no n_sessions', &
                     kv('ses1_1', 'n_sessions') < -1.0_dp)
    end subroutine test_sessions

    ! ---------------------------------------------------------------------------------------
    !> The correlation time of AR(1) residuals, x_k = rho x_(k-1) + e_k: (1 + rho)/(1 - rho)
    !! (19 for rho = 0.9), within 25 % on 20000 samples; 1 within 10 % for white noise.
    subroutine test_correlated(t)
        type(tester_t), intent(inout) :: t
        type(rng_t) :: g
        real(dp) :: x(20000), y(20000)
        integer :: k
        g = rng_stream(5, 0)
        x(1) = rng_normal(g)
        y(1) = rng_normal(g)
        do k = 2, size(x)
            x(k) = 0.9_dp*x(k - 1) + rng_normal(g)
            y(k) = rng_normal(g)
        end do
        call t%check_close('correlated: AR(1) rho 0.9, tau = 19', correlation_time(x), &
                           19.0_dp, rtol=0.25_dp)
        call t%check_close('correlated: white noise, tau = 1', correlation_time(y), 1.0_dp, &
                           rtol=0.1_dp)
    end subroutine test_correlated

    ! ---------------------------------------------------------------------------------------
    !> A video track: theta4 in degrees at 30 Hz from an angle tracker, the record starting
    !! mid-swing 5.3 s after the release (times from 0 at the record's start), a zero offset
    !! of 1.5 deg, noise 0.15 deg and 12 tracking glitches of 8 deg.  With t0 estimated (the
    !! release found at the first turning point), bias and amplitude estimated and
    !! loss = 'huber': I1 within 0.2 % (the glitches would pull least squares further).
    subroutine test_video(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(status_t) :: st
        type(rng_t) :: g
        real(dp), allocatable :: tt(:), th(:)
        character(len=:), allocatable :: rigtext, txt
        character(len=64) :: row
        integer :: i, n
        real(dp) :: i1_h, i1_s
        rigtext = HEAD//SUSP//BODY//"&start mode = 'raised', amplitude = 20 /"//NL
        call read_deck_text(SCR//'/video_truth.nml', rigtext//'&damping c_v = 1e-3 /'//NL// &
                            '&integration rtol = 1e-12, atol = 1e-14 /'//NL, d, st)
        n = 451
        allocate (tt(n), th(n))
        do i = 1, n
            tt(i) = 5.3_dp + (i - 1)/30.0_dp
        end do
        call record_model(rig_of(d), start_of(d), accuracy_of(d), tt, 0.0_dp, .false., th, st)
        call t%check('video: the truth record', st%code == 0)
        if (st%code /= 0) return
        g = rng_stream(31, 0)
        txt = 'frame;t;angle_deg'//NL
        do i = 1, n
            th(i) = th(i)/deg + 1.5_dp + 0.15_dp*rng_normal(g)
            if (mod(i, 37) == 0) th(i) = th(i) + 8.0_dp
            write (row, '(i0,a,f0.4,a,f0.4)') i, ';', tt(i) - 5.3_dp, ';', th(i)
            txt = txt//trim(row)//NL
        end do
        call write_text(SCR//'/video.csv', txt)
        call run_here('video', rigtext//"&damping c_v = 1e-3 /"//NL//"&measurement record = "// &
                      "'video.csv', record_columns = 2, 3, record_units = 'deg', loss = 'huber', "// &
                      "estimate = 'I1 amplitude t0 bias' /"//NL, st)
        call t%check('video: mid-swing, huber: converges', st%code == 0)
        if (st%code /= 0) then
            write (*, '(a)') '   '//st%msg
            return
        end if
        i1_h = kv('video', 'I1')
        call t%check_close('video: I1 within 0.2 % (huber)', i1_h, I1_TRUE, rtol=2.0e-3_dp)
        call run_here('video_ls', rigtext//"&damping c_v = 1e-3 /"//NL//"&measurement "// &
                      "record = 'video.csv', record_columns = 2, 3, record_units = 'deg', "// &
                      "estimate = 'I1 amplitude t0 bias' /"//NL, st)
        i1_s = kv('video_ls', 'I1')
        write (*, '(a,es12.5,a,es12.5)') '   video: I1 error, huber ', i1_h/I1_TRUE - 1.0_dp, &
            ', least squares ', i1_s/I1_TRUE - 1.0_dp
        call t%check('video: least squares converges too, and no closer than huber', &
                     st%code == 0 .and. abs(i1_s - I1_TRUE) >= 0.5_dp*abs(i1_h - I1_TRUE))
    end subroutine test_video

    ! ---------------------------------------------------------------------------------------
    !> The rig of SUSP/BODY released from 20 deg, its gyro's W (rad/s) for 10 s at 50 Hz with
    !! noise 0.002 rad/s (seed 41): times tt, values w (the model plus noise).
    subroutine reader_record(tt, w, st)
        real(dp), allocatable, intent(out) :: tt(:), w(:)
        type(status_t), intent(out) :: st
        type(deck_t) :: d
        type(rng_t) :: g
        integer :: i, n
        call read_deck_text(SCR//'/reader_truth.nml', HEAD//SUSP//BODY//"&start mode = "// &
                            "'raised', amplitude = 20 /"//NL//'&integration rtol = 1e-12, '// &
                            'atol = 1e-14 /'//NL, d, st)
        if (st%code /= 0) return
        n = 501
        allocate (tt(n), w(n))
        do i = 1, n
            tt(i) = (i - 1)/50.0_dp
        end do
        call record_model(rig_of(d), start_of(d), accuracy_of(d), tt, 0.0_dp, .true., w, st)
        g = rng_stream(41, 0)
        do i = 1, n
            w(i) = w(i) + 0.002_dp*rng_normal(g)
        end do
    end subroutine reader_record

    !> A deck of the reader's rig fitting record `rec` with the &measurement settings `more`.
    function reader_deck(rec, more, estimate) result(s)
        character(len=*), intent(in) :: rec, more
        character(len=*), intent(in), optional :: estimate     !! default 'I1 amplitude'
        character(len=:), allocatable :: s
        character(len=:), allocatable :: est
        est = 'I1 amplitude'
        if (present(estimate)) est = estimate
        s = HEAD//SUSP//BODY//"&start mode = 'raised', amplitude = 20 /"//NL// &
            "&integration rtol = 1e-10, atol = 1e-12 /"//NL//"&measurement record = '"// &
            rec//"', estimate = '"//est//"', u_l = 0.001, u_b = 0.0005, "//more//' /'//NL
    end function reader_deck

    !> One record written five ways, each giving the clean file's I1 and U: frame numbers
    !! with record_frame_rate; the value alone with record_frame_rate (the row's time);
    !! columns by their header names, the others text; a phone's export with four named
    !! columns (x, y, z and the magnitude) and no record_columns, its axis with the largest
    !! swing taken and named in the summary line and NAME.identify; a third column that is
    !! no u (a temperature) left unused, with a note, and taken as u only when
    !! record_columns names it (then a warning).
    subroutine test_reader(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(status_t) :: st
        type(rng_t) :: g
        real(dp), allocatable :: tt(:), w(:)
        character(len=:), allocatable :: plain, frames, named, phone, temp, line, dd
        character(len=160) :: row
        type(warning_t), allocatable :: wl(:)
        real(dp) :: i1c, uc, x, y
        integer :: i, ex
        call reader_record(tt, w, st)
        call t%check('reader: the truth record', st%code == 0)
        if (st%code /= 0) return
        g = rng_stream(42, 0)
        plain = '# t (s)  W (rad/s)'//NL
        frames = 'frame,W'//NL
        named = '"Status","Time (s)","Temp (C)","Gyroscope z (rad/s)","Note"'//NL
        phone = '"Time (s)","Gyroscope x (rad/s)","Gyroscope y (rad/s)",'// &
                '"Gyroscope z (rad/s)","Absolute (rad/s)"'//NL
        temp = ''
        do i = 1, size(tt)
            write (row, '(f0.2,1x,es17.9)') tt(i), w(i)
            plain = plain//trim(row)//NL
            write (row, '(i0,a,es17.9)') i - 1, ',', w(i)
            frames = frames//trim(row)//NL
            write (row, '(a,f0.2,a,f0.2,a,es17.9,a)') 'OK,', tt(i), ',', 21.0_dp + &
                0.3_dp*rng_normal(g), ',', w(i), ','//trim(merge('tracking lost', &
                'all good     ', mod(i, 9) == 0))
            named = named//trim(row)//NL
            x = 0.003_dp*rng_normal(g)
            y = 0.003_dp*rng_normal(g)
            write (row, '(f0.2,4(a,es17.9))') tt(i), ',', x, ',', y, ',', w(i), ',', &
                sqrt(x**2 + y**2 + w(i)**2)
            phone = phone//trim(row)//NL
            write (row, '(f0.2,1x,es17.9,1x,f0.2)') tt(i), w(i), 21.0_dp + 0.3_dp*rng_normal(g)
            temp = temp//trim(row)//NL
        end do
        call write_text(SCR//'/rd_plain.dat', plain)
        call write_text(SCR//'/rd_frames.csv', frames)
        call write_text(SCR//'/rd_named.csv', named)
        call write_text(SCR//'/rd_phone.csv', phone)
        call run_here('rd_plain', reader_deck('rd_plain.dat', "quantity = 'rate'"), st)
        call t%check('reader: the clean record fits', st%code == 0)
        if (st%code /= 0) then
            write (*, '(a)') '   '//st%msg
            return
        end if
        i1c = kv('rd_plain', 'I1')
        uc = kv('rd_plain', 'U_I1')
        call t%check_close('reader: the clean record, I1 within 0.1 %', i1c, I1_TRUE, &
                           rtol=1.0e-3_dp)
        call run_here('rd_frames', reader_deck('rd_frames.csv', "quantity = 'rate', "// &
                      'record_frame_rate = 50'), st)
        call same('frame numbers with record_frame_rate', 'rd_frames')
        call run_here('rd_rows', reader_deck('rd_frames.csv', "quantity = 'rate', "// &
                      'record_columns = 2, record_frame_rate = 50'), st)
        call same('the value alone, the time from the row and record_frame_rate', 'rd_rows')
        call run_here('rd_named', reader_deck('rd_named.csv', "record_columns = 'Time (s)', "// &
                      "'Gyroscope z (rad/s)'"), st)
        call same('columns by name (the unit from the name), text in the others', 'rd_named')
        call t%check('reader: named: the quantity from the column''s unit', &
                     file_has(SCR//'/rd_named.identify', 'quantity = rate'))
        call write_text(SCR//'/rd_phone.nml', reader_deck('rd_phone.csv', 'u_g = 0'))
        call run_deck(SCR//'/rd_phone.nml', SCR, line, st, warnings=wl)
        call same('a gyro export, no record_columns: the axis with the largest swing', &
                  'rd_phone')
        call t%check('reader: the axis taken named in the summary line', &
                     index(line, "record axis 'gyroscope z (rad/s)' (largest swing)") > 0)
        call t%check('reader: the axis taken named in NAME.identify', &
                     file_has(SCR//'/rd_phone.identify', 'record_axis = gyroscope z (rad/s) '// &
                              '(the axis with the largest swing)'))
        ! a third column that is no u
        dd = SCR//'/rd_temp'
        call fresh_dir(dd)
        call write_text(dd//'/rd_temp.dat', temp)
        call write_text(dd//'/rd_temp.nml', reader_deck('rd_temp.dat', "quantity = 'rate'"))
        ex = run(exe//' '//dd//'/rd_temp.nml --out '//dd, dd)
        call t%check('reader: a third column not named is no u: exit 0, a note', &
                     all([ex == 0, file_has(dd//'/stderr', 'its column 3 is not used'), &
                          message_lines(dd//'/stderr') == 0]))
        call t%check_close('reader: a third column not named: the clean I1', &
                           kv('rd_temp/rd_temp', 'I1'), i1c, rtol=1.0e-8_dp)
        call t%check_close('reader: a third column not named: the clean U', &
                           kv('rd_temp/rd_temp', 'U_I1'), uc, rtol=1.0e-6_dp)
        call write_text(dd//'/rd_temp3.nml', reader_deck('rd_temp.dat', "quantity = 'rate', "// &
                        'record_columns = 1, 2, 3'))
        ex = run(exe//' '//dd//'/rd_temp3.nml --out '//dd, dd)
        call t%check('reader: a temperature named as the u column: exit 0, one warning', &
                     all([ex == 0, count_lines(dd//'/stderr', 'warning') == 1, &
                          file_has(dd//'/stderr', 'not small against its swing')]))
    contains
        subroutine same(what, name)
            character(len=*), intent(in) :: what, name
            call t%check('reader: '//what//': exit 0', st%code == 0)
            if (st%code /= 0) then
                write (*, '(a)') '   '//st%msg
                return
            end if
            call t%check_close('reader: '//what//': the clean I1', kv(name, 'I1'), i1c, &
                               rtol=1.0e-8_dp)
            call t%check_close('reader: '//what//': the clean U', kv(name, 'U_I1'), uc, &
                               rtol=1.0e-6_dp)
        end subroutine same
    end subroutine test_reader

    !> Record mistakes, each ending the same way in both builds: a unit in the column's name
    !! against record_units (one line naming record_units); radians declared degrees (one
    !! line naming record_units, before the fit or, t0 estimated, after it from the fitted
    !! amplitude); a clock that does not start at the release with t0 not estimated (one
    !! line at once, naming t0); an angle declared a rate (one line naming quantity); frame
    !! numbers without record_frame_rate (naming it).  Dropouts and spikes: the classical
    !! period from the samples the fit keeps (the linear formula within 0.2 % of the clean
    !! record's).
    subroutine test_record_mistakes(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(status_t) :: st
        type(deck_t) :: d
        real(dp), allocatable :: tt(:), w(:), th(:)
        character(len=:), allocatable :: dd, named, shifted, frames, angle, drop, clean, line
        character(len=80) :: row
        real(dp) :: lin_clean
        integer :: i
        call reader_record(tt, w, st)
        call t%check('mistakes: the truth record', st%code == 0)
        if (st%code /= 0) return
        call read_deck_text(SCR//'/angle_truth.nml', HEAD//SUSP//BODY//"&start mode = "// &
                            "'raised', amplitude = 20 /"//NL, d, st)
        allocate (th(size(tt)))
        call record_model(rig_of(d), start_of(d), accuracy_of(d), tt, 0.0_dp, .false., th, st)
        call t%check('mistakes: the truth angle record', st%code == 0)
        if (st%code /= 0) return
        dd = SCR//'/mistakes'
        call fresh_dir(dd)
        named = '"Time (s)","Gyroscope z (rad/s)"'//NL
        shifted = ''
        frames = 'frame,W'//NL
        angle = ''
        drop = ''
        clean = ''
        do i = 1, size(tt)
            write (row, '(f0.2,a,es17.9)') tt(i), ',', w(i)
            named = named//trim(row)//NL
            write (row, '(f0.2,1x,es17.9)') tt(i) + 4.0e4_dp, w(i)
            shifted = shifted//trim(row)//NL
            write (row, '(i0,a,es17.9)') i - 1, ',', w(i)
            frames = frames//trim(row)//NL
            write (row, '(f0.2,1x,es17.9)') tt(i), th(i)
            angle = angle//trim(row)//NL
            write (row, '(f0.2,1x,es17.9)') tt(i), w(i)
            clean = clean//trim(row)//NL
            ! 26 dropouts to 0 and 5 spikes
            write (row, '(f0.2,1x,es17.9)') tt(i), merge(0.0_dp, w(i), mod(i, 19) == 7) + &
                merge(3.0_dp, 0.0_dp, mod(i, 97) == 50)
            drop = drop//trim(row)//NL
        end do
        call write_text(dd//'/named.csv', named)
        call write_text(dd//'/shifted.dat', shifted)
        call write_text(dd//'/frames.csv', frames)
        call write_text(dd//'/angle.dat', angle)
        call write_text(dd//'/drop.dat', drop)
        call write_text(dd//'/clean.dat', clean)
        call refused('a unit in the name against record_units', 'conflict', &
                     reader_deck('named.csv', "record_columns = 'time (s)', 'gyroscope z "// &
                     "(rad/s)', record_units = 'deg/s'"), "record_units = 'deg/s'")
        call refused('rad/s declared deg/s', 'raddeg', &
                     reader_deck('named.csv', "record_columns = 1, 2, record_units = 'deg/s'"), &
                     'record_units')
        call refused('rad/s declared deg/s, t0 estimated: the fitted amplitude', 'raddeg_t0', &
                     reader_deck('named.csv', "record_columns = 1, 2, record_units = 'deg/s'", &
                     'I1 amplitude t0'), 'record_units')
        call refused('a clock far from the release, t0 not estimated', 'shifted', &
                     reader_deck('shifted.dat', "quantity = 'rate'"), 't0 in &measurement estimate')
        call refused('frame numbers without record_frame_rate', 'frames', &
                     reader_deck('frames.csv', "quantity = 'rate'"), 'record_frame_rate = F')
        call refused('an angle declared a rate', 'anglerate', &
                     reader_deck('angle.dat', "quantity = 'rate'"), "quantity = 'angle'")
        ! dropouts and spikes: the classical value from the samples the fit keeps
        call write_text(dd//'/clean.nml', reader_deck('clean.dat', "quantity = 'rate'"))
        call run_deck(dd//'/clean.nml', dd, line, st)
        lin_clean = kv('mistakes/clean', 'I1_linear')
        call t%check('mistakes: the clean record''s classical value', st%code == 0 .and. &
                     lin_clean > 0.0_dp)
        call write_text(dd//'/drop.nml', reader_deck('drop.dat', "quantity = 'rate', "// &
                        "loss = 'huber'"))
        call run_deck(dd//'/drop.nml', dd, line, st)
        call t%check('mistakes: dropouts and spikes, huber: exit 0', st%code == 0)
        if (st%code /= 0) then
            write (*, '(a)') '   '//st%msg
            return
        end if
        call t%check_close('mistakes: dropouts: I1 within 0.1 %', kv('mistakes/drop', 'I1'), &
                           I1_TRUE, rtol=1.0e-3_dp)
        call t%check_close('mistakes: dropouts: the classical value as the clean record''s', &
                           kv('mistakes/drop', 'I1_linear'), lin_clean, rtol=2.0e-3_dp)
    contains
        subroutine refused(what, name, deck_text, word)
            character(len=*), intent(in) :: what, name, deck_text, word
            integer :: ex
            logical :: ok
            call write_text(dd//'/'//name//'.nml', deck_text)
            ex = run(exe//' '//dd//'/'//name//'.nml --out '//dd//'/o_'//name, dd)
            ok = all([ex == 2, message_lines(dd//'/stderr') == 1, file_has(dd//'/stderr', word)])
            call t%check('mistakes: '//what//': exit 2, one line naming '//word, ok)
            if (.not. ok) call execute_command_line('cat '//dd//'/stderr')
        end subroutine refused
    end subroutine test_record_mistakes

    !> No figure script (plots/*.gp, *.gpi) holds the title of a deck of input/: figures take
    !! their titles from the data.
    subroutine test_titles(t)
        type(tester_t), intent(inout) :: t
        integer :: ex
        call execute_command_line('for f in input/*.nml input/*/*.nml; do '// &
            't=$(grep -o "title = ''[^'']*''" "$f" | head -n 1 | sed "s/title = ''//; '// &
            's/''$//"); [ -n "$t" ] && grep -lF "$t" plots/*.gp plots/*.gpi; done | '// &
            'grep -q .', exitstat=ex)
        call t%check('titles: no deck''s title in plots/*.gp or *.gpi', ex /= 0)
    end subroutine test_titles

    !> The sensitivity (fourth field) of the budget row `name` of a .identify (0 when none).
    real(dp) function row_sensitivity(path, name) result(c)
        character(len=*), intent(in) :: path, name
        character(len=512) :: line
        character(len=32) :: w
        real(dp) :: v, uu
        integer :: u, ios
        c = 0.0_dp
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, name//' ') /= 1) cycle
            read (line, *, iostat=ios) w, v, uu, c
            exit
        end do
        close (u)
    end function row_sensitivity

end module test_measure
