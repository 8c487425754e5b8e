!> Tests of the analyses of a platform (&suspension cables >= 3): the Floquet analysis of
!! its torsion (module platform_floquet) against the paper's reduced equation (centred) and
!! against the turn about the mass centre, M g (R^2 - e^2)/L (off the axis); the multipliers
!! of a conservative orbit (their product 1); the decks of floquet, chart, design and
!! simulate through the program; and the platforms the program refuses (exit 2 or 4, one
!! line, no file).
module test_platform_analyses
    use kinds, only: dp, deg
    use status, only: status_t
    use testing, only: tester_t, write_text, exists, fresh_dir, run, count_lines, no_nan, &
                       read_kv_text, message_lines, file_has
    use text, only: sci
    use integrators, only: SOLVER_LSODA
    use geometry, only: pendulum_t
    use floquet, only: torsion_period
    use platform_geometry, only: platform_t, regular_platform
    use platform_model, only: check_platform
    use platform_floquet, only: platform_floquet_t, platform_floquet_analysis, &
                                platform_floquet_point
    implicit none
    private

    public :: run_platform_analysis_tests, run_platform_refusal_tests

    character(len=*), parameter :: SCR = 'build/test_platform_analyses'
    real(dp), parameter :: GRAV = 9.81_dp

contains

    !> The analyses of a platform (suite platform).
    subroutine run_platform_analysis_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        if (t%want('platform floquet: a centred trifilar against the paper''s reduced '// &
                   'equation')) call test_floquet_centred(t)
        if (t%want('platform floquet: off the axis, the turn about the mass centre')) &
            call test_floquet_offset(t)
        if (t%want('platform decks: floquet, chart, design and simulate')) &
            call test_platform_decks(t, exe)
    end subroutine run_platform_analysis_tests

    !> The body of these tests: diag(Ixx, Iyy, Izz) in the body's frame.
    pure function diag3(a, b, c) result(jb)
        real(dp), intent(in) :: a, b, c
        real(dp) :: jb(3, 3)
        jb = 0.0_dp
        jb(1, 1) = a
        jb(2, 2) = b
        jb(3, 3) = c
    end function diag3

    ! ---------------------------------------------------------------------------------------
    !> A centred trifilar (R = 0.5, R' = 0.4, l = 1.2, mass 1.3, the mass centre 0.1 below the
    !! attachments) at 30 degrees: its orbit is pure torsion (no shooting), its period that of
    !! the paper's eqs. (45)-(48) with b = 2R, b' = 2R' (floquet's torsion_period), the orbit
    !! closes, and the four multipliers of a conservative orbit have the product 1.
    subroutine test_floquet_centred(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pl
        type(platform_floquet_t) :: res
        type(pendulum_t) :: p
        type(status_t) :: st
        real(dp), parameter :: r = 0.5_dp, rp = 0.4_dp, l = 1.2_dp, m = 1.3_dp, izz = 0.09_dp
        real(dp) :: perb, ts, prod
        pl = regular_platform(3, r, rp, l, m, diag3(0.05_dp, 0.06_dp, izz), [0.0_dp, 0.0_dp], &
                              0.1_dp, GRAV)
        call check_platform(pl, st)
        call t%check('platform floquet: the centred rig is accepted', st%code == 0)
        call platform_floquet_analysis(pl, 30.0_dp*deg, 1.0e-10_dp, SOLVER_LSODA, res, st)
        call t%check('platform floquet: the centred analysis succeeds', st%code == 0)
        ! the bifilar equivalent in the paper's scaled units (b' = m = g = 1)
        p = pendulum_t()
        p%big_b = r/rp
        p%big_l = l/(2.0_dp*rp)
        p%big_lp = p%big_l
        p%inertia = izz/(m*(2.0_dp*rp)**2)
        p%r = 0.5_dp
        p%lambda = 0.0_dp
        ts = sqrt(2.0_dp*rp/GRAV)
        call torsion_period(p, 30.0_dp*deg, 3, perb, st)
        call t%check_close('platform floquet: the period of the centred torsion = eqs. '// &
                           '(45)-(48) with b = 2R, b'' = 2R''', res%period, perb*ts, 1.0e-8_dp, &
                           0.0_dp)
        call t%check('platform floquet: pure torsion needs no shooting', &
                     res%shooting_iterations == 0 .and. res%continuation_steps == 0)
        call t%check('platform floquet: the centred orbit closes (|x''|, |y''| at T/2 < 1e-9)', &
                     res%orbit_closure < 1.0e-9_dp)
        prod = product(abs(res%multipliers(1:4)))
        call t%check_close('platform floquet: the product of the four multipliers is 1 '// &
                           '(a conservative orbit)', prod, 1.0_dp, 1.0e-6_dp, 0.0_dp)
        call t%check('platform floquet: stable means max modulus <= 1 + 1e-6', &
                     res%stable .eqv. (res%max_modulus <= 1.0_dp + 1.0e-6_dp))
        call t%check('platform floquet: two trivial multipliers, both 1', &
                     count(res%trivial) == 2 .and. all(abs(res%multipliers(5:6) - 1.0_dp) == &
                     0.0_dp))
        write (*, '(a,es10.3,a,es10.3)') '  platform floquet, centred: period ', res%period, &
            ', max modulus ', res%max_modulus
    end subroutine test_floquet_centred

    ! ---------------------------------------------------------------------------------------
    !> The published trifilar with a test mass (R = R' = 0.135 m, l = 1 m, the body 0.869 kg):
    !! with the mass centre e = 18 mm off the axis the small torsion (1 degree) turns about
    !! the mass centre with the restoring torque M g (R^2 - e^2)/L, so that its period over
    !! the centred one is R/sqrt(R^2 - e^2) (0.9 % longer), to 1e-4; the shooting found the
    !! orbit (it carries a sway: the turning point off the rest), and it closes.
    subroutine test_floquet_offset(t)
        type(tester_t), intent(inout) :: t
        type(platform_t) :: pc, po
        type(platform_floquet_t) :: rc, ro
        type(status_t) :: st, st2
        real(dp), parameter :: r = 0.135_dp, l = 1.0_dp, m = 0.869_dp, e = 0.018_dp
        real(dp) :: ratio, predicted
        pc = regular_platform(3, r, r, l, m, diag3(0.005_dp, 0.005_dp, 0.0093_dp), &
                              [0.0_dp, 0.0_dp], 0.0_dp, GRAV)
        po = regular_platform(3, r, r, l, m, diag3(0.005_dp, 0.005_dp, 0.0093_dp), &
                              [e, 0.0_dp], 0.0_dp, GRAV)
        call check_platform(pc, st)
        call check_platform(po, st2)
        call t%check('platform floquet: the test-mass rigs are accepted', &
                     st%code == 0 .and. st2%code == 0)
        call platform_floquet_analysis(pc, 1.0_dp*deg, 1.0e-11_dp, SOLVER_LSODA, rc, st)
        call platform_floquet_analysis(po, 1.0_dp*deg, 1.0e-11_dp, SOLVER_LSODA, ro, st2)
        call t%check('platform floquet: both analyses succeed', st%code == 0 .and. st2%code == 0)
        ratio = ro%period/rc%period
        predicted = r/sqrt(r**2 - e**2)
        call t%check_close('platform floquet: off the axis the period over the centred one '// &
                           'is R/sqrt(R^2 - e^2) (M g (R^2 - e^2)/L)', ratio, predicted, &
                           1.0e-4_dp, 0.0_dp)
        call t%check('platform floquet: ignoring the offset would be off by more than 0.5 %', &
                     abs(ratio - 1.0_dp) > 5.0e-3_dp)
        call t%check('platform floquet: the off-axis orbit was shot (its turning point '// &
                     'is off the rest) and closes', ro%shooting_iterations >= 1 .and. &
                     maxval(abs(ro%y0(1:2))) > 0.0_dp .and. ro%orbit_closure < 1.0e-8_dp)
        write (*, '(a,es12.5,a,es12.5)') '  platform floquet, off the axis: period ratio ', &
            ratio, ', predicted ', predicted
    end subroutine test_floquet_offset

    ! ---------------------------------------------------------------------------------------
    !> The analyses of a trifilar deck through the program: floquet (its period that of
    !! platform_floquet_analysis on the same platform), a 3 x 3 chart over cg_offset and
    !! cg_depth (its centred point's modulus and period those of platform_floquet_point), a
    !! small design by radius and length, and simulate (its files, no NaN).
    subroutine test_platform_decks(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o
        character(len=*), parameter :: RIG = &
            '&suspension cables = 3, radius = 0.135, radius_prime = 0.135, l = 1.0, '// &
            'g = 9.81 /'//new_line('a')// &
            '&body mass = 0.869, inertia = 0.0093, 0.005, 0.005, cg_depth = 0.05, '// &
            'cg_offset = 0.0, 0.0 /'//new_line('a')
        type(platform_t) :: pl
        type(platform_floquet_t) :: res
        type(status_t) :: st
        character(len=64) :: val
        real(dp) :: per, xs(4), pchart, mchart, mdirect, pdirect
        integer :: ex, u, ios, k
        character(len=1024) :: line
        logical :: found
        d = SCR//'/decks'
        call fresh_dir(d)
        o = d//'/out'
        pl = regular_platform(3, 0.135_dp, 0.135_dp, 1.0_dp, 0.869_dp, &
                              diag3(0.005_dp, 0.005_dp, 0.0093_dp), [0.0_dp, 0.0_dp], 0.05_dp, &
                              GRAV)
        ! floquet
        call write_text(d//'/fl.nml', "&scene analyses = 'floquet' /"//new_line('a')//RIG// &
                        '&floquet amplitude = 20 /'//new_line('a'))
        ex = run(exe//' '//d//'/fl.nml --out '//o, d)
        call t%check('platform decks: floquet exits 0 with its file', all([ex == 0, &
                     exists(o//'/fl.floquet')]))
        call read_kv_text(o//'/fl.floquet', 'period', val)
        read (val, *, iostat=ios) per
        if (ios /= 0) per = -1.0_dp
        call check_platform(pl, st)
        call platform_floquet_analysis(pl, 20.0_dp*deg, 1.0e-10_dp, SOLVER_LSODA, res, st)
        call t%check_close('platform decks: the deck''s floquet period is the model''s', per, &
                           res%period, 1.0e-13_dp, 0.0_dp)
        call t%check('platform decks: the summary line says floquet', &
                     file_has(d//'/stdout', 'fl: floquet period'))
        ! chart over cg_offset and cg_depth
        call write_text(d//'/ch.nml', "&scene analyses = 'chart' /"//new_line('a')//RIG// &
                        '&floquet amplitude = 20 /'//new_line('a')// &
                        "&chart x = 'cg_offset', x_min = 0.0, x_max = 0.02, nx = 3, "// &
                        "y = 'cg_depth', y_min = 0.0, y_max = 0.05, ny = 3 /"//new_line('a'))
        ex = run(exe//' '//d//'/ch.nml --out '//o, d)
        call t%check('platform decks: chart exits 0 with its file, no NaN', all([ex == 0, &
                     exists(o//'/ch.chart.dat'), no_nan(o)]))
        call t%check('platform decks: the chart has its 9 rows', &
                     count_lines(o//'/ch.chart.dat') - count_lines(o//'/ch.chart.dat', '#', &
                     .true.) - 3 == 9)
        ! its point (cg_offset 0, cg_depth 0.05) against the model
        found = .false.
        pchart = -9.0_dp
        mchart = -9.0_dp
        open (newunit=u, file=o//'/ch.chart.dat', status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
            read (line, *, iostat=k) xs
            if (k /= 0) cycle
            if (xs(1) == 0.0_dp .and. abs(xs(2) - 0.05_dp) < 1.0e-15_dp) then
                found = .true.
                mchart = xs(3)
                pchart = xs(4)
            end if
        end do
        if (ios /= -1 .or. found) close (u)
        call platform_floquet_point(pl, 20.0_dp, 1.0e-10_dp, SOLVER_LSODA, mdirect, pdirect)
        call t%check('platform decks: the chart''s centred point is the model''s (modulus '// &
                     sci(mchart)//', period '//sci(pchart)//')', found .and. &
                     abs(pchart - pdirect) <= 1.0e-13_dp*pdirect .and. &
                     abs(mchart - mdirect) <= 1.0e-13_dp)
        call t%check('platform decks: the chart''s periods grow with the offset', &
                     chart_periods_grow(o//'/ch.chart.dat'))
        ! design by radius and length
        call write_text(d//'/de.nml', "&scene analyses = 'design' /"//new_line('a')//RIG// &
                        '&design l_min = 0.6, l_max = 1.4, nl = 4, radius_min = 0.1, '// &
                        'radius_max = 0.2, nradius = 2, amplitude_max = 20, '// &
                        'n_amplitudes = 1 /'//new_line('a'))
        ex = run(exe//' '//d//'/de.nml --out '//o, d)
        call t%check('platform decks: design exits 0 with a recommended radius', all([ex == 0, &
                     file_has(o//'/de.design', 'recommended_radius = ')]))
        ! simulate
        call write_text(d//'/si.nml', "&scene analyses = 'simulate' /"// &
                        new_line('a')//'&suspension cables = 3, radius = 0.135, '// &
                        'radius_prime = 0.135, l = 1.0, g = 9.81 /'//new_line('a')// &
                        '&body mass = 0.869, inertia = 0.0093, 0.005, 0.005, cg_depth = 0.05, '// &
                        'cg_offset = 0.018, 0.0 /'//new_line('a')// &
                        '&start amplitude = 20 /'//new_line('a')// &
                        '&integration tau_end = 5, dtau_out = 0.1 /'//new_line('a'))
        ex = run(exe//' '//d//'/si.nml --out '//o, d)
        call t%check('platform decks: simulate exits 0 with .dat and .summary, no NaN', &
                     all([ex == 0, exists(o//'/si.dat'), exists(o//'/si.summary'), &
                     no_nan(o)]))
        call read_kv_text(o//'/si.summary', 'max_abs_energy_error', val)
        read (val, *, iostat=ios) per
        call t%check('platform decks: simulate''s energy error is below 1e-8 J', ios == 0 .and. &
                     abs(per) < 1.0e-8_dp)
    end subroutine test_platform_decks

    !> Whether, at each cg_depth of a chart over (cg_offset, cg_depth), the period grows with
    !! the offset (the restoring torque M g (R^2 - e^2)/L shrinks).
    logical function chart_periods_grow(path)
        character(len=*), intent(in) :: path
        real(dp) :: v(4), per(3, 3)
        integer :: u, ios, k, n
        character(len=1024) :: line
        chart_periods_grow = .false.
        n = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
            read (line, *, iostat=k) v
            if (k /= 0) cycle
            n = n + 1
            if (n > 9) exit
            per(mod(n - 1, 3) + 1, (n - 1)/3 + 1) = v(4)    ! (y index, x index): y fastest
        end do
        close (u)
        if (n /= 9) return
        chart_periods_grow = all(per(:, 2) > per(:, 1)) .and. all(per(:, 3) > per(:, 2))
    end function chart_periods_grow

    ! ---------------------------------------------------------------------------------------
    !> Platforms the program refuses (suite robust): attachments on a line, a cable shorter
    !! than the height it must bridge, Floquet of four (elastic) cables (exit 2), a body
    !! whose mass centre is above its tipping height (exit 4, the height named); one line on
    !! standard error, no file.
    subroutine run_platform_refusal_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d, o
        character(len=*), parameter :: NL = new_line('a')
        character(len=*), parameter :: BODY = '&body mass = 1, inertia = 0.02, 0.01, 0.01 /'// &
            NL//'&integration tau_end = 1, dtau_out = 0.1 /'//NL
        integer :: ex
        if (.not. t%want('robust: bad platforms: exit 2 or 4, one line, no file')) return
        d = SCR//'/refusals'
        call fresh_dir(d)
        o = d//'/out'
        call write_text(d//'/collinear.nml', "&scene analyses = 'simulate' /"//NL// &
            '&suspension cables = 3, support_points(:,1) = 0, 0, 0, '// &
            'support_points(:,2) = 1, 0, 0, support_points(:,3) = 2, 0, 0, '// &
            'body_points(:,1) = 0, 0.1, 0, body_points(:,2) = 0.1, -0.1, 0, '// &
            'body_points(:,3) = -0.1, -0.1, 0, lengths = 1, 1, 1, g = 9.81 /'//NL//BODY)
        ex = run(exe//' '//d//'/collinear.nml --out '//o, d)
        call t%check('robust: collinear attachments: exit 2, one line naming them', all([ex == 2, &
                     message_lines(d//'/stderr') == 1, file_has(d//'/stderr', 'collinear'), &
                     .not. exists(o//'/collinear.dat')]))
        call write_text(d//'/short.nml', "&scene analyses = 'simulate' /"//NL// &
            '&suspension cables = 3, support_points(:,1) = 0.1, 0, 0, '// &
            'support_points(:,2) = -0.05, 0.0866, 0, support_points(:,3) = -0.05, -0.0866, 0.5, '// &
            'body_points(:,1) = 0.1, 0, 0, body_points(:,2) = -0.05, 0.0866, 0, '// &
            'body_points(:,3) = -0.05, -0.0866, 0, lengths = 1, 1, 0.3, g = 9.81 /'//NL//BODY)
        ex = run(exe//' '//d//'/short.nml --out '//o, d)
        call t%check('robust: a cable shorter than its height difference: exit 2, one line', &
                     all([ex == 2, message_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'lengths(3)'), .not. exists(o//'/short.dat')]))
        call write_text(d//'/tip.nml', "&scene analyses = 'simulate' /"//NL// &
            '&suspension cables = 3, radius = 0.1, radius_prime = 0.05, l = 1.0, g = 9.81 /'// &
            NL//'&body mass = 1, inertia = 0.02, 0.01, 0.01, cg_depth = -2 /'//NL// &
            '&integration tau_end = 1, dtau_out = 0.1 /'//NL)
        ex = run(exe//' '//d//'/tip.nml --out '//o, d)
        call t%check('robust: a body above its tipping height: exit 4, one line naming '// &
                     'the height', all([ex == 4, message_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'tips over'), &
                     file_has(d//'/stderr', 'cg_depth = -1.0'), .not. exists(o//'/tip.dat')]))
        call write_text(d//'/quad.nml', "&scene analyses = 'floquet' /"//NL// &
            '&suspension cables = 4, radius = 0.1, radius_prime = 0.1, l = 1.0, g = 9.81 /'// &
            NL//BODY)
        ex = run(exe//' '//d//'/quad.nml --out '//o, d)
        call t%check('robust: floquet of four cables: exit 2, one line', all([ex == 2, &
                     message_lines(d//'/stderr') == 1, .not. exists(o//'/quad.floquet')]))
    end subroutine run_platform_refusal_tests

end module test_platform_analyses
