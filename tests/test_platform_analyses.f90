!> Tests of the analyses of a platform (&suspension cables >= 3): the Floquet analysis of
!! its torsion (module platform_floquet) against the paper's reduced equation (centred) and
!! against the turn about the mass centre, M g (R^2 - e^2)/L (off the axis); the multipliers
!! of a conservative orbit (their product 1); the decks of floquet, chart, design and
!! simulate through the program; identify on a platform (periods and records, the body
!! above or below the cables, its mass centre off the axis, the budget and Monte Carlo);
!! and the platforms the program refuses (exit 2 or 4, one line, no file).
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
    use rig, only: rig_t, start_t, accuracy_t
    use period_inversion, only: rig_period_s
    use platform_measure, only: platform_record
    use random, only: rng_t, rng_stream, rng_normal
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
        if (t%want('platform identify: periods and records, the body above the cables')) &
            call test_identify_depth(t, exe)
        if (t%want('platform identify: the mass centre off the axis, budget and Monte Carlo')) &
            call test_identify_offset(t, exe)
        if (t%want('platform identify: four cables, the mass centre off the axis (elastic)')) &
            call test_identify_quad(t, exe)
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

    !> The rig of the identify tests: a trifilar (R = R' = 0.135 m, l = 1 m), 2.048 kg,
    !! I1 = 0.0243 kg m^2, the mass centre at cg_offset (x) and cg_depth.
    function identify_rig(offset, depth) result(rg)
        real(dp), intent(in) :: offset, depth
        type(rig_t) :: rg
        rg = rig_t()
        rg%cables = 3
        rg%b = 0.27_dp
        rg%b_prime = 0.27_dp
        rg%l = 1.0_dp
        rg%l_prime = 1.0_dp
        rg%g = GRAV
        rg%mass = 2.048_dp
        rg%inertia = [0.0243_dp, 0.014_dp, 0.014_dp]
        rg%c_v = 0.0_dp
        rg%c_q = 0.0_dp
        rg%r = sqrt((0.135_dp + offset)**2 + depth**2)
        rg%lambda = atan2(depth, 0.135_dp + offset)
    end function identify_rig

    !> A record of the platform rg released at amp degrees: omega about the vertical every
    !! 0.02 s for `dur` s, plus normal noise of 0.002 rad/s (seed 5), written to path.
    subroutine write_platform_record(rg, amp, dur, path, ok)
        type(rig_t), intent(in) :: rg
        real(dp), intent(in) :: amp, dur
        character(len=*), intent(in) :: path
        logical, intent(out) :: ok
        type(start_t) :: st
        type(accuracy_t) :: acc
        type(status_t) :: stat
        type(rng_t) :: g
        real(dp), allocatable :: tt(:), v(:)
        integer :: i, n, u
        n = nint(dur/0.02_dp) + 1
        allocate (tt(n), v(n))
        do i = 1, n
            tt(i) = 0.02_dp*(i - 1)
        end do
        st%mode = 'raised'
        st%amplitude = amp
        call platform_record(rg, st, acc, tt, 0.0_dp, .true., v, stat)
        ok = stat%code == 0
        g = rng_stream(5, 0)
        open (newunit=u, file=path, status='replace', action='write')
        write (u, '(a)') '# t (s)  W (rad/s)'
        do i = 1, n
            write (u, '(f10.4,es20.10)') tt(i), v(i) + 0.002_dp*rng_normal(g)
        end do
        close (u)
    end subroutine write_platform_record

    !> A value of a key = value file as a number (-huge when absent or unreadable).
    real(dp) function kv_real(path, key) result(x)
        character(len=*), intent(in) :: path, key
        character(len=64) :: val
        integer :: ios
        call read_kv_text(path, key, val)
        read (val, *, iostat=ios) x
        if (ios /= 0) x = -huge(1.0_dp)
    end function kv_real

    ! ---------------------------------------------------------------------------------------
    !> A centred body on a trifilar, 0.05 and 0.2 m above the cables (cg_depth < 0) and as
    !! far below: pure torsion does not depend on the depth, so periods and a record give
    !! the I1 of the body below within 1e-6, with the budget (u_cg_depth) and Monte Carlo;
    !! the periods (exact torsion at I1 = 0.0243) give the truth to 1e-6.  The record is the
    !! platform's own motion (three cables hold the tilt; the bifilar's tilt about CD, a mode
    !! the platform does not have, is not in the fit).  A body above the height at which the
    !! platform tips (R' = 0.05: 0.35 m) is refused with exit 4 naming that height; and a
    !! body off the axis of four cables with exit 2.
    subroutine test_identify_depth(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: NL = new_line('a')
        real(dp), parameter :: depths(4) = [0.05_dp, 0.2_dp, -0.05_dp, -0.2_dp]
        character(len=:), allocatable :: d, o, rigtext, name
        type(accuracy_t) :: acc
        type(status_t) :: st
        real(dp) :: t5, t20, ip(4), ir(4), uu(4), umc(4)
        integer :: k, ex, exr(4), exq(4)
        logical :: ok, okr
        d = SCR//'/idepth'
        call fresh_dir(d)
        o = d//'/out'
        call rig_period_s(identify_rig(0.0_dp, 0.05_dp), acc, 0.0243_dp, 5.0_dp, t5, st)
        ok = st%code == 0
        call rig_period_s(identify_rig(0.0_dp, 0.05_dp), acc, 0.0243_dp, 20.0_dp, t20, st)
        ok = ok .and. st%code == 0
        call write_platform_record(identify_rig(0.0_dp, 0.05_dp), 10.0_dp, 8.0_dp, &
                                   d//'/rec.dat', okr)
        do k = 1, 4
            rigtext = "&scene analyses = 'identify' /"//NL// &
                '&suspension cables = 3, radius = 0.135, radius_prime = 0.135, l = 1.0, '// &
                'g = 9.81 /'//NL//'&body mass = 2.048, inertia = 0.022, 0.014, 0.014, '// &
                'cg_depth = '//sci(depths(k))//', cg_offset = 0, 0 /'//NL
            name = 'p'//achar(48 + k)
            call write_text(d//'/'//name//'.nml', rigtext//'&measurement periods = '// &
                sci(t5, 15)//', '//sci(t20, 15)//', amplitudes = 5, 20, u_period = 1e-4, '// &
                'u_mass = 0.001, u_l = 0.001, u_cg_depth = 0.01, monte_carlo = 20 /'//NL)
            exq(k) = run(exe//' '//d//'/'//name//'.nml --out '//o, d)
            ip(k) = kv_real(o//'/'//name//'.identify', 'I1')
            name = 'r'//achar(48 + k)
            call write_text(d//'/'//name//'.nml', rigtext//"&start mode = 'raised', "// &
                'amplitude = 10 /'//NL//"&measurement record = 'rec.dat', "// &
                "quantity = 'rate', estimate = 'I1 amplitude', u_mass = 0.001, u_l = 0.001, "// &
                'u_cg_depth = 0.01, monte_carlo = 10 /'//NL)
            exr(k) = run(exe//' '//d//'/'//name//'.nml --out '//o, d)
            ir(k) = kv_real(o//'/'//name//'.identify', 'I1')
            uu(k) = kv_real(o//'/'//name//'.identify', 'U_I1')
            umc(k) = kv_real(o//'/'//name//'.identify', 'u_I1_monte_carlo')
        end do
        call t%check('platform identify: the truth''s periods and record are made', ok .and. okr)
        call t%check('platform identify: periods, the body above or below: exit 0', &
                     all(exq == 0))
        call t%check('platform identify: a record, the body above or below: exit 0 with '// &
                     'Monte Carlo', all(exr == 0) .and. all(umc > 0.0_dp))
        call t%check_close('platform identify: periods give the truth', ip(1), 0.0243_dp, &
                           1.0e-6_dp, 0.0_dp)
        call t%check('platform identify: periods of the body 0.05 and 0.2 m above give '// &
                     'the I1 of the body below within 1e-6', &
                     all(abs(ip(2:4)/ip(1) - 1.0_dp) < 1.0e-6_dp))
        call t%check('platform identify: a record of the body 0.05 and 0.2 m above gives '// &
                     'the I1 of the body below within 1e-6', &
                     all(abs(ir(2:4)/ir(1) - 1.0_dp) < 1.0e-6_dp))
        call t%check('platform identify: the record''s I1 covers the truth', &
                     abs(ir(1) - 0.0243_dp) < uu(1))
        write (*, '(a,3es10.2)') '  platform identify, periods at cg_depth 0.2, -0.05, -0.2 '// &
            'over 0.05, less 1: ', ip(2:4)/ip(1) - 1.0_dp
        write (*, '(a,3es10.2)') '  platform identify, a record at cg_depth 0.2, -0.05, -0.2 '// &
            'over 0.05, less 1: ', ir(2:4)/ir(1) - 1.0_dp
        ! above its tipping height
        call write_text(d//'/tip.nml', "&scene analyses = 'identify' /"//NL// &
            '&suspension cables = 3, radius = 0.135, radius_prime = 0.05, l = 1.0, '// &
            'g = 9.81 /'//NL//'&body mass = 2.048, inertia = 0.022, 0.014, 0.014, '// &
            'cg_depth = -1, cg_offset = 0, 0 /'//NL//'&measurement periods = 1.6, '// &
            'amplitudes = 5 /'//NL)
        ex = run(exe//' '//d//'/tip.nml --out '//o, d)
        call t%check('platform identify: a body above its tipping height: exit 4, one line '// &
                     'naming the height', all([ex == 4, message_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'tips over'), &
                     file_has(d//'/stderr', 'above cg_depth = -3.48'), &
                     .not. exists(o//'/tip.identify')]))
    end subroutine test_identify_depth

    ! ---------------------------------------------------------------------------------------
    !> The body's mass centre 18 mm off the axis of the trifilar (along x, and as far along
    !! y): periods of the platform's periodic torsion at I1 = 0.0243 give the truth to 1e-6,
    !! with a budget row for cg_offset, and for cg_offset_y when the offset is along y
    !! (-2 e I1/(R^2 - e^2) to 2 %), and a Monte Carlo u within
    !! 25 % of the budget's; a record of the platform's motion gives I1 within U, and with
    !! the offset ignored (cg_offset = 0) about e^2/(R^2 - e^2) = 1.8 % more.
    subroutine test_identify_offset(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: NL = new_line('a')
        real(dp), parameter :: e = 0.018_dp, rr = 0.135_dp
        character(len=:), allocatable :: d, o, head
        type(accuracy_t) :: acc
        type(status_t) :: st
        real(dp) :: t5, t20, ipx, ipy, u1, umc, sens, sensy, irec, urec, inai
        integer :: exx, exy, exr, exn
        logical :: ok, okr
        d = SCR//'/ioffset'
        call fresh_dir(d)
        o = d//'/out'
        call rig_period_s(identify_rig(e, 0.05_dp), acc, 0.0243_dp, 5.0_dp, t5, st)
        ok = st%code == 0
        call rig_period_s(identify_rig(e, 0.05_dp), acc, 0.0243_dp, 20.0_dp, t20, st)
        ok = ok .and. st%code == 0
        head = "&scene analyses = 'identify' /"//NL// &
            '&suspension cables = 3, radius = 0.135, radius_prime = 0.135, l = 1.0, '// &
            'g = 9.81 /'//NL//'&body mass = 2.048, inertia = 0.022, 0.014, 0.014, '// &
            'cg_depth = 0.05, '
        call write_text(d//'/px.nml', head//'cg_offset = 0.018, 0 /'//NL// &
            '&measurement periods = '//sci(t5, 15)//', '//sci(t20, 15)//', amplitudes = 5, '// &
            '20, u_period = 1e-4, u_mass = 0.001, u_l = 0.001, u_cg_offset = 0.002, '// &
            'monte_carlo = 40 /'//NL)
        exx = run(exe//' '//d//'/px.nml --out '//o, d)
        ipx = kv_real(o//'/px.identify', 'I1')
        u1 = kv_real(o//'/px.identify', 'u_I1')
        umc = kv_real(o//'/px.identify', 'u_I1_monte_carlo')
        sens = budget_sensitivity(o//'/px.identify', 'cg_offset')
        ! the same periods with the offset along y (the trifilar's torsion at small amplitude
        ! turns about the mass centre whatever the direction; at 20 degrees nearly so)
        call write_text(d//'/py.nml', head//'cg_offset = 0, 0.018 /'//NL// &
            '&measurement periods = '//sci(t5, 15)//', amplitudes = 5, u_period = 1e-4, '// &
            'u_cg_offset = 0.002 /'//NL)
        exy = run(exe//' '//d//'/py.nml --out '//o, d)
        ipy = kv_real(o//'/py.identify', 'I1')
        sensy = budget_sensitivity(o//'/py.identify', 'cg_offset_y')
        call t%check('platform identify off the axis: periods made, exit 0 with the budget '// &
                     'and Monte Carlo', ok .and. exx == 0 .and. exy == 0 .and. umc > 0.0_dp)
        call t%check_close('platform identify off the axis: periods give the truth', ipx, &
                           0.0243_dp, 1.0e-6_dp, 0.0_dp)
        call t%check_close('platform identify off the axis: the offset along y as along x', &
                           ipy, 0.0243_dp, 1.0e-4_dp, 0.0_dp)
        call t%check_close('platform identify off the axis: the budget''s cg_offset '// &
                           'sensitivity is -2 e I1/(R^2 - e^2)', sens, &
                           -2.0_dp*e*0.0243_dp/(rr**2 - e**2), 0.02_dp, 0.0_dp)
        call t%check_close('platform identify off the axis: along y, the budget''s '// &
                           'cg_offset_y sensitivity is -2 e I1/(R^2 - e^2)', sensy, &
                           -2.0_dp*e*0.0243_dp/(rr**2 - e**2), 0.02_dp, 0.0_dp)
        call t%check_close('platform identify off the axis: Monte Carlo''s u is the '// &
                           'budget''s', umc, u1, 0.25_dp, 0.0_dp)
        ! a record, with the offset and without it
        call write_platform_record(identify_rig(e, 0.05_dp), 10.0_dp, 8.0_dp, d//'/rec.dat', &
                                   okr)
        call write_text(d//'/rx.nml', head//'cg_offset = 0.018, 0 /'//NL// &
            "&start mode = 'raised', amplitude = 10 /"//NL//"&measurement record = "// &
            "'rec.dat', quantity = 'rate', estimate = 'I1 amplitude', u_mass = 0.001, "// &
            'u_l = 0.001, u_cg_offset = 0.001 /'//NL)
        exr = run(exe//' '//d//'/rx.nml --out '//o, d)
        irec = kv_real(o//'/rx.identify', 'I1')
        urec = kv_real(o//'/rx.identify', 'U_I1')
        call write_text(d//'/rn.nml', head//'cg_offset = 0, 0 /'//NL// &
            "&start mode = 'raised', amplitude = 10 /"//NL//"&measurement record = "// &
            "'rec.dat', quantity = 'rate', estimate = 'I1 amplitude' /"//NL)
        exn = run(exe//' '//d//'/rn.nml --out '//o, d)
        inai = kv_real(o//'/rn.identify', 'I1')
        call t%check('platform identify off the axis: the records fit (exit 0)', &
                     okr .and. exr == 0 .and. exn == 0)
        call t%check('platform identify off the axis: the record''s I1 covers the truth', &
                     abs(irec - 0.0243_dp) < urec)
        call t%check_close('platform identify off the axis: the offset ignored, I1 is '// &
                           'e^2/(R^2 - e^2) more', inai/irec - 1.0_dp, e**2/(rr**2 - e**2), &
                           0.03_dp, 0.0_dp)
        write (*, '(a,es16.8,a,es10.3,a,es10.3,a,es12.5,a,f7.3,a)') '  platform identify off '// &
            'the axis: periods I1 ', ipx, ', u ', u1, ', Monte Carlo u ', umc, '; record I1 ', &
            irec, ', offset ignored +', 100*(inai/irec - 1.0_dp), ' %'
    end subroutine test_identify_offset

    ! ---------------------------------------------------------------------------------------
    !> Four cables with the body's mass centre 18 mm off the axis (elastic cables, &cables
    !! stiffness by default 1e6): the period at 5 degrees is the small-amplitude torsion
    !! about the mass centre 2 pi (I1 L/(M g (R^2 - e^2)))^(1/2) times 1 + theta^2/16 to
    !! 5e-4; periods of I1 = 0.0243 give it back within 1e-6 and within U, labelled
    !! 'platform elastic'; a mass centre 1e-6 m off the axis (the elastic model) gives the
    !! centred body's I1 (pure torsion) to 1e-6; a body above its tipping height: exit 4.
    subroutine test_identify_quad(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: NL = new_line('a')
        real(dp), parameter :: e = 0.018_dp, rr = 0.135_dp, i1 = 0.0243_dp, m = 2.048_dp
        character(len=:), allocatable :: d, o, head
        type(accuracy_t) :: acc
        type(status_t) :: st
        type(rig_t) :: rg
        real(dp) :: t5, tc, tsmall, iq, uq, ic, ie
        integer :: ex(3), ext
        logical :: ok
        d = SCR//'/iquad'
        call fresh_dir(d)
        o = d//'/out'
        rg = identify_rig(e, 0.05_dp)
        rg%cables = 4
        call rig_period_s(rg, acc, i1, 5.0_dp, t5, st)
        ok = st%code == 0
        rg = identify_rig(0.0_dp, 0.05_dp)
        rg%cables = 4
        call rig_period_s(rg, acc, i1, 5.0_dp, tc, st)
        ok = ok .and. st%code == 0
        tsmall = 2.0_dp*acos(-1.0_dp)*sqrt(i1*1.0_dp/(m*GRAV*(rr**2 - e**2)))* &
                 (1.0_dp + (5.0_dp*deg)**2/16.0_dp)
        head = "&scene analyses = 'identify' /"//NL// &
            '&suspension cables = 4, radius = 0.135, radius_prime = 0.135, l = 1.0, '// &
            'g = 9.81 /'//NL//'&body mass = 2.048, inertia = 0.022, 0.014, 0.014, '// &
            'cg_depth = 0.05, '
        call write_text(d//'/q.nml', head//'cg_offset = 0.018, 0 /'//NL// &
            '&measurement periods = '//sci(t5, 15)//', amplitudes = 5, u_period = 1e-4 /'//NL)
        ex(1) = run(exe//' '//d//'/q.nml --out '//o, d)
        iq = kv_real(o//'/q.identify', 'I1')
        uq = kv_real(o//'/q.identify', 'U_I1')
        call write_text(d//'/c.nml', head//'cg_offset = 0, 0 /'//NL// &
            '&measurement periods = '//sci(tc, 15)//', amplitudes = 5, u_period = 1e-4 /'//NL)
        ex(2) = run(exe//' '//d//'/c.nml --out '//o, d)
        ic = kv_real(o//'/c.identify', 'I1')
        call write_text(d//'/ce.nml', head//'cg_offset = 1e-6, 0 /'//NL// &
            '&measurement periods = '//sci(tc, 15)//', amplitudes = 5, u_period = 1e-4 /'//NL)
        ex(3) = run(exe//' '//d//'/ce.nml --out '//o, d)
        ie = kv_real(o//'/ce.identify', 'I1')
        call t%check('quadrifilar identify off the axis: periods made, exit 0', &
                     ok .and. all(ex == 0))
        call t%check_close('quadrifilar off the axis: the elastic period is the torsion '// &
                           'about the mass centre', t5, tsmall, 5.0e-4_dp, 0.0_dp)
        call t%check_close('quadrifilar identify off the axis: periods give the truth', iq, &
                           i1, 1.0e-6_dp, 0.0_dp)
        call t%check('quadrifilar identify off the axis: the truth within U', &
                     abs(iq - i1) < uq .and. uq > 0.0_dp)
        call t%check('quadrifilar identify off the axis: period model platform elastic', &
                     file_has(o//'/q.identify', 'period_model = platform elastic'))
        call t%check_close('quadrifilar identify: 1e-6 m off the axis (elastic) gives the '// &
                           'centred body''s I1 (pure torsion)', ie, ic, 1.0e-6_dp, 0.0_dp)
        write (*, '(a,es16.8,a,es10.3,a,es10.3)') '  quadrifilar identify off the axis: I1 ', &
            iq, ', U ', uq, '; elastic 1e-6 off over pure torsion, less 1: ', ie/ic - 1.0_dp
        ! above its tipping height, off the axis
        call write_text(d//'/tip.nml', "&scene analyses = 'identify' /"//NL// &
            '&suspension cables = 4, radius = 0.135, radius_prime = 0.05, l = 1.0, '// &
            'g = 9.81 /'//NL//'&body mass = 2.048, inertia = 0.022, 0.014, 0.014, '// &
            'cg_depth = -1, cg_offset = 0.001, 0 /'//NL//'&measurement periods = 1.6, '// &
            'amplitudes = 5 /'//NL)
        ext = run(exe//' '//d//'/tip.nml --out '//o, d)
        call t%check('quadrifilar identify off the axis, above its tipping height: exit 4, '// &
                     'one line', all([ext == 4, message_lines(d//'/stderr') == 1, &
                     file_has(d//'/stderr', 'tips over'), .not. exists(o//'/tip.identify')]))
    end subroutine test_identify_quad

    !> The sensitivity of the budget's row `name` in an identify file (-huge when absent).
    real(dp) function budget_sensitivity(path, name) result(s)
        character(len=*), intent(in) :: path, name
        character(len=1024) :: line
        character(len=32) :: w
        real(dp) :: v, uu
        integer :: u, ios
        s = -huge(1.0_dp)
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, name//' ') /= 1) cycle
            read (line, *, iostat=ios) w, v, uu, s
            exit
        end do
        close (u)
    end function budget_sensitivity

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
