!> Tests of the rig design (module design, analysis `design`): the recommendation
!! checked by an independent Floquet analysis (100 times tighter tolerance, twice the
!! amplitudes), the band edges against a stability chart of the same body, the predicted
!! precision and the linear formula's error against the classical limit (exact formulas),
!! a range with no qualifying candidate (exit 4, one line, no file), bad &design input (one
!! line, no file), and the same file from 1 and 2 threads.
module test_design
    use kinds, only: dp, deg, pi
    use status, only: status_t
    use testing, only: tester_t, write_text, file_has, count_lines, run, shell_count, &
                       scratch_dir, fresh_dir, empty_dir, no_nan
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of
    use geometry, only: pendulum_t
    use rig, only: make_pendulum
    use floquet, only: floquet_result_t, floquet_analysis
    use stability, only: run_chart
    use design, only: design_result_t, design_sweep, candidate_precision, candidate_rig, &
                      design_rig_of, &
                      DESIGN_TOLERANCE, MARGIN_FRACTION, EDGE_RTOL
    use period_inversion, only: input_u_t
    use text, only: itoa, sci
    implicit none
    private

    public :: run_design_tests

    character(len=*), parameter :: SCR = 'build/test_design'
    character, parameter :: NL = new_line('a')
    !> The block of input/box_design.nml (SI units): b' = 0.2 m, 2 kg, hung from its top edges.
    character(len=*), parameter :: BOX = &
        "&scene title = 'design test', analyses = 'design' /"//NL// &
        '&suspension b = 0.2, b_prime = 0.2, l = 0.6, l_prime = 0.6, g = 9.80665 /'//NL// &
        '&body mass = 2.0, inertia = 0.007083333333333333, 0.11333333333333333, '// &
        '0.10708333333333333,'//NL// &
        '      r = 0.412310562561766, lambda = 1.325817663668033, sway_depth = 0.8 /'//NL// &
        '&floquet rtol = 1e-8 /'//NL
    !> Around the tongue of instability at l = 5.4 ... 5.7 b' (1.08 ... 1.14 m).
    character(len=*), parameter :: AROUND_TONGUE = '&design l_min = 0.9, l_max = 1.2, '// &
        'nl = 16, amplitude_max = 50, n_amplitudes = 4 /'

contains

    subroutine run_design_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        type(deck_t) :: d
        type(design_result_t) :: res
        type(status_t) :: st
        logical :: have, want_rec, want_edges
        call fresh_dir(SCR)
        have = .false.
        want_rec = t%want('design: the recommendation is stable, checked independently')
        want_edges = t%want('design: band edges agree with the stability chart')
        if (want_rec .or. want_edges) then
            call write_text(SCR//'/tongue.nml', BOX//AROUND_TONGUE//NL)
            call read_deck(SCR//'/tongue.nml', d, st)
            call t%check('design: the test deck reads', st%code == 0)
            if (st%code == 0) call design_sweep(d, res, '')
            have = st%code == 0
        end if
        if (have .and. want_rec) call test_recommendation(t, d, res)
        if (have .and. want_edges) call test_edges(t, d, res)
        if (t%want('design: precision and linear error at the classical limit')) &
            call test_classical(t)
        if (t%want('design: no qualifying candidate is exit 4, one line, no file')) &
            call test_none(t, exe)
        if (t%want('design: bad &design input is one line, no file')) call test_bad(t, exe)
        if (t%want('design: 1 and 2 threads give the same file (b swept too)')) &
            call test_threads(t, exe)
        if (t%want('design: b_prime swept, precision at amplitude_measure')) &
            call test_b_prime(t)
    end subroutine run_design_tests

    !> The recommended rig, analysed again at rtol 100 times tighter and at twice as many
    !! amplitudes (j amplitude_max / (2 n_amplitudes)): stable at every one.  Also what the
    !! recommendation promises: stable at the design's amplitudes, the margin, the smallest
    !! u(I1)/I1 among the qualifying candidates.
    subroutine test_recommendation(t, d, res)
        type(tester_t), intent(inout) :: t
        type(deck_t), intent(in) :: d
        type(design_result_t), intent(in) :: res
        type(pendulum_t) :: p
        type(floquet_result_t) :: fr
        type(status_t) :: st
        real(dp) :: l, b, worst, amp
        integer :: j, n2, i, m
        logical :: ok, best
        call t%check('recommendation: found', res%found)
        if (.not. res%found) return
        l = res%ls(res%il)
        b = res%bs(res%ib)
        call t%check('recommendation: stable at the design''s amplitudes', &
                     res%stable(res%il, res%ib) .and. all(res%modulus(:, res%il, res%ib) <= &
                     1.0_dp + DESIGN_TOLERANCE) .and. all(res%modulus(:, res%il, res%ib) > 0))
        call t%check('recommendation: margin >= 5% of l ('//sci(res%margin(res%il, res%ib))// &
                     ' at l = '//sci(l)//')', res%margin(res%il, res%ib) >= MARGIN_FRACTION*l)
        ! the smallest u(I1)/I1 among candidates stable with the margin
        best = .true.
        do m = 1, size(res%bs)
            do i = 1, size(res%ls)
                if (res%stable(i, m) .and. res%margin(i, m) >= MARGIN_FRACTION*res%ls(i)) &
                    best = best .and. res%u_rel(i, m) >= res%u_rel(res%il, res%ib)
            end do
        end do
        call t%check('recommendation: the smallest u(I1)/I1 among the qualifying', best)
        ! independently: rtol / 100, twice the amplitudes
        call make_pendulum(candidate_rig(rig_of(d), l, b, res%bps(res%ib)), p, st)
        n2 = 2*d%design%n_amplitudes
        ok = st%code == 0
        worst = 0.0_dp
        do j = 1, n2
            amp = d%design%amplitude_max*j/n2
            call floquet_analysis(p, amp*deg, d%floquet%rtol/100.0_dp, d%floquet%segments, &
                                  fr, st)
            ok = ok .and. st%code == 0
            if (st%code == 0) worst = max(worst, fr%max_modulus)
        end do
        write (*, '(a)') '   recommendation: l = '//sci(l)//', largest multiplier at '// &
            itoa(n2)//' amplitudes, rtol '//sci(d%floquet%rtol/100.0_dp, 0)//': '//sci(worst, 9)
        call t%check('recommendation (l = '//sci(l)//'): at rtol '// &
                     sci(d%floquet%rtol/100.0_dp, 0)//' and '//itoa(n2)// &
                     ' amplitudes every analysis succeeds', ok)
        call t%check('recommendation: stable at all '//itoa(n2)//' amplitudes (largest '// &
                     'multiplier '//sci(worst, 9)//')', ok .and. worst <= 1.0_dp + DESIGN_TOLERANCE)
        call t%check('recommendation: the range has an unstable band (the test means '// &
                     'something)', size(res%unstable) > 0 .and. res%n_edges >= 2)
    end subroutine test_recommendation

    !> A stability chart over l (the chart's x = l/b') at the design's amplitudes (its y), on a
    !! grid four times finer: every refined edge of the design inside the range lies in the
    !! chart interval where the modulus crosses 1 + tolerance (to 1 % of the chart's step;
    !! an edge at a grid midpoint, unrefined, misses by up to half the design's step, twice
    !! the chart's), and every chart point inside a design unstable band (more than one chart
    !! step from its ends) is unstable there.
    subroutine test_edges(t, d, res)
        type(tester_t), intent(inout) :: t
        type(deck_t), intent(in) :: d
        type(design_result_t), intent(in) :: res
        type(deck_t) :: c
        type(status_t) :: st
        character(len=:), allocatable :: dir
        real(dp), allocatable :: x(:), mods(:, :)
        real(dp) :: secs, h, e, lo, hi, g
        integer :: nstable, nx, ny, j, k, i, nedge, ncheck, u, ios, row
        logical :: okc, oki, stab_a, stab_b, same_amps
        real(dp) :: v(4)
        character(len=512) :: line
        dir = SCR//'/chart'
        call scratch_dir(dir)
        c = d
        c%name = 'edges'
        c%scene%analyses = 'chart'
        c%chart%x = 'l'
        c%chart%y = 'amplitude'
        nx = 4*(d%design%nl - 1) + 1
        ny = d%design%n_amplitudes
        c%chart%nx = nx
        c%chart%ny = ny
        c%chart%x_min = d%design%l_min/d%suspension%b_prime
        c%chart%x_max = d%design%l_max/d%suspension%b_prime
        c%chart%y_min = d%design%amplitude_max/ny
        c%chart%y_max = d%design%amplitude_max
        call run_chart(c, dir, nstable, secs, st)
        call t%check('edges: the chart runs', st%code == 0)
        if (st%code /= 0) return
        allocate (x(nx), mods(nx, ny))
        open (newunit=u, file=dir//'/edges.chart.dat', status='old', action='read', iostat=ios)
        row = 0
        same_amps = .true.
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
            read (line, *, iostat=ios) v
            if (ios /= 0) exit
            row = row + 1
            i = (row - 1)/ny + 1
            j = mod(row - 1, ny) + 1
            x(i) = v(1)*d%suspension%b_prime
            mods(i, j) = v(3)
            if (abs(v(2) - res%amps(j)) > 1.0e-12_dp*res%amps(j)) same_amps = .false.
        end do
        close (u)
        call t%check('edges: all chart rows read, at the design''s amplitudes', &
                     row == nx*ny .and. same_amps)
        if (row /= nx*ny) return
        h = x(2) - x(1)
        nedge = 0
        okc = .true.
        ncheck = 0
        oki = .true.
        do k = 1, size(res%unstable)
            j = res%unstable(k)%ia
            lo = res%unstable(k)%l_from
            hi = res%unstable(k)%l_to
            ! each refined edge inside the range: a chart crossing within one step
            do i = 1, 2
                e = merge(lo, hi, i == 1)
                if (e <= res%ls(1) .or. e >= res%ls(size(res%ls))) cycle
                nedge = nedge + 1
                if (.not. crossing_near(e, j)) okc = .false.
            end do
            ! chart points well inside the band are unstable
            do i = 1, nx
                if (x(i) > lo + h .and. x(i) < hi - h) then
                    ncheck = ncheck + 1
                    oki = oki .and. mods(i, j) > 1.0_dp + DESIGN_TOLERANCE
                end if
            end do
        end do
        write (*, '(a)') '   edges: '//itoa(nedge)//' refined edges inside the range, '// &
            itoa(ncheck)//' chart points inside design bands, chart step '//sci(h)
        call t%check('edges: '//itoa(nedge)//' refined edges, each in the chart interval '// &
                     '(step '//sci(h)//') where the modulus crosses', nedge >= 2 .and. okc)
        call t%check('edges: '//itoa(ncheck)//' chart points inside design bands are '// &
                     'unstable in the chart', oki)
        ! each edge bisected from the grid's step down to EDGE_RTOL l
        g = res%ls(2) - res%ls(1)
        call t%check('edges: bisection refined them (steps from the grid''s step to '// &
                     'EDGE_RTOL l)', res%n_bisection_points >= &
                     res%n_edges*floor(log(g/(EDGE_RTOL*res%ls(size(res%ls))))/log(2.0_dp)))
    contains
        logical function crossing_near(e, jj)
            real(dp), intent(in) :: e
            integer, intent(in) :: jj
            integer :: kk
            crossing_near = .false.
            do kk = 1, nx - 1
                if (x(kk + 1) < e - 0.01_dp*h .or. x(kk) > e + 0.01_dp*h) cycle
                stab_a = mods(kk, jj) >= 0.0_dp .and. mods(kk, jj) <= 1.0_dp + DESIGN_TOLERANCE
                stab_b = mods(kk + 1, jj) >= 0.0_dp .and. &
                    mods(kk + 1, jj) <= 1.0_dp + DESIGN_TOLERANCE
                if (stab_a .neqv. stab_b) crossing_near = .true.
            end do
        end function crossing_near
    end subroutine test_edges

    !> Cables 1000 b' long, where the exact rig becomes the classical one (corrections of
    !! order (b/l)^2 = 1e-6): at 0.5 degrees the predicted u(I1)/I1 is the classical
    !! propagation through I1 = m g b b' T^2/(16 pi^2 l) (mass, b, b', each cable carrying
    !! half of l, 2 u_T/T); at 25 degrees the linear formula's error is that of a pendulum
    !! with the potential (1 - cos q), (2 K(sin(A/2))/pi)^2 - 1 (K by the AGM).
    subroutine test_classical(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(status_t) :: st
        type(input_u_t) :: u
        real(dp) :: period, urel, lin, expect, l, k, a, g, an
        integer :: it
        call write_text(SCR//'/classic.nml', BOX//'&design l_min = 0.9, l_max = 1.2 /'//NL)
        call read_deck(SCR//'/classic.nml', d, st)
        call t%check('classical: the deck reads', st%code == 0)
        if (st%code /= 0) return
        l = 1000.0_dp*d%suspension%b_prime
        u = input_u_t(mass=1.0e-3_dp, l=1.0e-3_dp, l_prime=1.0e-3_dp, b=5.0e-4_dp, &
                      b_prime=5.0e-4_dp, g=0.0_dp, period=1.0e-4_dp, amplitude=0.0_dp)
        call candidate_precision(design_rig_of(d), l, d%suspension%b, d%suspension%b_prime, &
                                 0.5_dp, u, period, urel, lin, st)
        call t%check('classical: precision computed', st%code == 0)
        expect = sqrt((u%mass/d%body%mass)**2 + (u%b/d%suspension%b)**2 + &
                      (u%b_prime/d%suspension%b_prime)**2 + 0.5_dp*(u%l/l)**2 + &
                      (2.0_dp*u%period/period)**2)
        call t%check_close('classical: u(I1)/I1 = the linear propagation at 0.5 deg', urel, &
                           expect, rtol=1.0e-4_dp)
        call t%check_close('classical: linear error at 0.5 deg ~ A^2/8', lin, &
                           (0.5_dp*deg)**2/8.0_dp, rtol=2.0e-2_dp)
        call candidate_precision(design_rig_of(d), l, d%suspension%b, d%suspension%b_prime, &
                                 25.0_dp, u, period, urel, lin, st)
        k = sin(0.5_dp*25.0_dp*deg)
        a = 1.0_dp
        g = sqrt(1.0_dp - k*k)
        do it = 1, 8
            an = 0.5_dp*(a + g)
            g = sqrt(a*g)
            a = an
        end do
        expect = (1.0_dp/a)**2 - 1.0_dp    ! (2K/pi)^2 - 1 with K = pi/(2 AGM(1, k'))
        call t%check_close('classical: linear error at 25 deg = (2K/pi)^2 - 1', lin, expect, &
                           atol=2.0e-6_dp)
    end subroutine test_classical

    !> Ranges with no qualifying candidate: unstable everywhere (short cables, up to 50
    !! degrees), and stable everywhere but too narrow for the margin (the range's ends count);
    !! and a range whose shortest cables cannot reach the raised position (-1, still a run).
    subroutine test_none(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d
        integer :: ex
        d = SCR//'/none'
        call execute_command_line('rm -rf '//d//' && mkdir -p '//d//'/out')
        call write_text(d//'/short.nml', BOX//'&design l_min = 0.1, l_max = 0.13, nl = 4, '// &
                        'amplitude_max = 50, n_amplitudes = 6 /'//NL)
        ex = run(exe//' '//d//'/short.nml --out '//d//'/out', d)
        call t%check('none: unstable range: exit 4', ex == 4)
        call t%check('none: ... one stderr line naming the deck, nothing on stdout', &
                     all([count_lines(d//'/stderr') == 1, count_lines(d//'/stdout') == 0, &
                     file_has(d//'/stderr', 'bifilar: error (model no longer valid): '//d// &
                     '/short.nml: design: no candidate qualifies')]))
        call t%check('none: ... says 0 are stable and suggests a range', &
                     all([file_has(d//'/stderr', ' 0 are stable'), &
                     file_has(d//'/stderr', 'try l_min = ')]))
        call t%check('none: ... no file written', empty_dir(d//'/out'))
        call write_text(d//'/narrow.nml', BOX//'&design l_min = 0.9, l_max = 0.91, nl = 3, '// &
                        'amplitude_max = 30, n_amplitudes = 2 /'//NL)
        ex = run(exe//' '//d//'/narrow.nml --out '//d//'/out', d)
        call t%check('none: a stable range narrower than the margin: exit 4', ex == 4)
        call t%check('none: ... one line: all 3 stable, none with the margin, a wider range', &
                     all([count_lines(d//'/stderr') == 1, file_has(d//'/stderr', ' 3 are stable'), &
                     file_has(d//'/stderr', 'none lies 5%'), &
                     file_has(d//'/stderr', 'try l_min = ')]))
        call t%check('none: ... no file written', empty_dir(d//'/out'))
        ! cables too short to reach the raised position of 50 degrees (l < 0.0845 m): -1
        call write_text(d//'/reach.nml', BOX//'&design l_min = 0.05, l_max = 1.2, nl = 5, '// &
                        'amplitude_max = 50, n_amplitudes = 2 /'//NL)
        ex = run(exe//' '//d//'/reach.nml --out '//d//'/out', d)
        call t%check('none: candidates whose cables cannot reach: exit 0 all the same', ex == 0)
        call t%check('none: ... their row is -1 (l = 0.05: stable 0, max_modulus -1, the '// &
                     'modulus at 50 deg -1)', shell_count('awk ''/^# l b b_prime stable/{on=1; next} '// &
                     'on && NF && $1 < 0.06 && $4 == 0 && $5 == -1 && $NF == -1'' '//d// &
                     '/out/reach.design | wc -l', d) == 1)
        call t%check('none: ... no NaN, Inf or ****', no_nan(d//'/out'))
    end subroutine test_none

    !> Bad &design values: exit 2, one stderr line naming the deck and the variable, no file.
    subroutine test_bad(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        ! the last: a smallest amplitude of 1e-7 degrees (Floquet's products underflow
        ! below about 1e-170 degrees: SIGFPE, found by the fuzz test through &floquet)
        character(len=*), parameter :: CASES(15) = [character(len=80) :: &
            'l_min = 1.2, l_max = 0.9|l_max', 'l_min = 0.9, l_max = 0.9|l_max', &
            'nl = 1|nl', 'nl = -3|nl', 'amplitude_max = 0|amplitude_max', &
            'amplitude_max = 90.5|amplitude_max', 'amplitude_max = -10|amplitude_max', &
            'u_mass = -0.001|u_mass', 'u_l = -1e-3|u_l', 'u_b = -1e-4|u_b', &
            'u_period = -1e-4|u_period', 'l_min = NaN|l_min', &
            'nb = 2, b_min = 0, b_max = 0|b_min', 'u_period = 100|u_period', &
            'amplitude_max = 1e-7|amplitude_max']
        character(len=*), parameter :: LAMBDA = 'lambda = 1.325817663668033'
        integer :: il
        character(len=:), allocatable :: d, c, var, nm, decks
        integer :: k, ex, bar
        logical :: ok
        d = SCR//'/bad'
        call execute_command_line('rm -rf '//d//' && mkdir -p '//d//'/out')
        decks = ''
        do k = 1, size(CASES)
            c = trim(CASES(k))
            bar = index(c, '|')
            nm = d//'/bad'//itoa(k)//'.nml'
            call write_text(nm, BOX//'&design nl = 3, n_amplitudes = 1, '//c(1:bar - 1)//' /'//NL)
            decks = decks//' '//nm
        end do
        ! a body whose mass centre is off the bisector of AB: no pure torsion
        il = index(BOX, LAMBDA)
        call write_text(d//'/off.nml', BOX(1:il - 1)//'lambda = 1.2'//BOX(il + len(LAMBDA):)// &
                        '&design nl = 3 /'//NL)
        decks = decks//' '//d//'/off.nml'
        ex = run(exe//decks//' --out '//d//'/out', d)
        call t%check('bad: '//itoa(size(CASES) + 1)//' decks, exit 2', ex == 2)
        call t%check('bad: one stderr line per deck, nothing on stdout', &
                     all([count_lines(d//'/stderr') == size(CASES) + 1, &
                     count_lines(d//'/stdout') == 0]))
        call t%check('bad: a body without pure torsion is refused before computing', &
                     file_has(d//'/stderr', d//'/off.nml: analyses = ''design'' needs a body '// &
                     'for which pure torsion on equal cables is an exact motion'))
        do k = 1, size(CASES)
            c = trim(CASES(k))
            bar = index(c, '|')
            var = c(bar + 1:)
            nm = d//'/bad'//itoa(k)//'.nml'
            c = 'bifilar: error (bad input): '//nm//': &design '//var//' = '
            ok = all([file_has(d//'/stderr', c), file_has(d//'/stderr', 'allowed')])
            c = trim(CASES(k))
            call t%check('bad: '//c(1:bar - 1)//': names &design '//var//' and what is allowed', &
                         ok)
        end do
        call t%check('bad: the negative uncertainty is called so', &
                     file_has(d//'/stderr', 'a negative uncertainty'))
        call t%check('bad: no file written', empty_dir(d//'/out'))
    end subroutine test_bad

    !> A design over l and b with 1 and 2 OpenMP threads: the same file, byte for byte; one
    !! row per candidate, no NaN; the recommended b one of the grid's.
    subroutine test_threads(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=:), allocatable :: d
        integer :: ex1, ex2, exc
        d = SCR//'/threads'
        call execute_command_line('rm -rf '//d//' && mkdir -p '//d//'/t1 '//d//'/t2')
        call write_text(d//'/lb.nml', BOX//'&design l_min = 0.9, l_max = 1.2, nl = 7, '// &
                        'b_min = 0.18, b_max = 0.22, nb = 2, amplitude_max = 50, '// &
                        'n_amplitudes = 3 /'//NL)
        ex1 = run('OMP_NUM_THREADS=1 '//exe//' '//d//'/lb.nml --out '//d//'/t1', d)
        ex2 = run('OMP_NUM_THREADS=2 '//exe//' '//d//'/lb.nml --out '//d//'/t2', d)
        call t%check('threads: both runs exit 0', ex1 == 0 .and. ex2 == 0)
        call execute_command_line('cmp -s '//d//'/t1/lb.design '//d//'/t2/lb.design', &
                                  exitstat=exc)
        call t%check('threads: 1 and 2 threads give the same .design', exc == 0)
        call t%check('threads: 14 candidate rows (7 l x 2 b)', shell_count('awk ''/^# l b '// &
                     'b_prime stable/{on=1; next} /^# stable bands/{on=0} on && NF'' '//d// &
                     '/t2/lb.design | wc -l', d) == 14)
        call t%check('threads: recommended b is 0.18 or 0.22', &
                     any([file_has(d//'/t2/lb.design', 'recommended_b = 1.8'), &
                     file_has(d//'/t2/lb.design', 'recommended_b = 2.2')]))
        call t%check('threads: no NaN, Inf or ****', no_nan(d//'/t2'))
    end subroutine test_threads

    !> b' swept with b (three body spacings): the candidates are the pairs, each pair's
    !! precision is candidate_precision's for that (l, b, b'); a wider b' measures I1 more
    !! precisely (u_b over b' falls).  The precision is predicted at amplitude_measure, and
    !! does not move when amplitude_max (the stability range) widens.
    subroutine test_b_prime(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d, d2
        type(design_result_t) :: res, res2
        type(status_t) :: st
        type(input_u_t) :: u
        real(dp) :: period, urel, lin
        integer :: m, i
        call write_text(SCR//'/bprime.nml', BOX//'&design l_min = 0.9, l_max = 1.2, nl = 4, '// &
                        'b_prime_min = 0.16, b_prime_max = 0.24, nb_prime = 3, '// &
                        'amplitude_max = 40, n_amplitudes = 2, amplitude_measure = 20 /'//NL)
        call read_deck(SCR//'/bprime.nml', d, st)
        call t%check('b_prime: the deck reads', st%code == 0)
        if (st%code /= 0) return
        call design_sweep(d, res, '')
        call t%check('b_prime: 4 x 3 candidates, b'' 0.16, 0.20, 0.24 with the deck''s b', &
                     size(res%ls)*size(res%bs) == 12 .and. all(abs(res%bps - &
                     [0.16_dp, 0.2_dp, 0.24_dp]) < 1.0e-15_dp) .and. all(res%bs == d%suspension%b))
        u = input_u_t(mass=d%design%u_mass, l=d%design%u_l, l_prime=d%design%u_l, &
                      b=d%design%u_b, b_prime=d%design%u_b, period=d%design%u_period)
        call candidate_precision(design_rig_of(d), res%ls(2), res%bs(3), res%bps(3), 20.0_dp, &
                                 u, period, urel, lin, st)
        call t%check_close('b_prime: a pair''s precision is candidate_precision''s', &
                           res%u_rel(2, 3), urel, rtol=1.0e-14_dp)
        call t%check('b_prime: a wider b'' measures I1 more precisely', &
                     all([(res%u_rel(i, 1) > res%u_rel(i, 2) .and. &
                           res%u_rel(i, 2) > res%u_rel(i, 3), i=1, 4)]))
        call write_text(SCR//'/bprime2.nml', BOX//'&design l_min = 0.9, l_max = 1.2, nl = 4, '// &
                        'b_prime_min = 0.16, b_prime_max = 0.24, nb_prime = 3, '// &
                        'amplitude_max = 60, n_amplitudes = 2, amplitude_measure = 20 /'//NL)
        call read_deck(SCR//'/bprime2.nml', d2, st)
        call design_sweep(d2, res2, '')
        call t%check('b_prime: the precision does not move with amplitude_max', &
                     all(res2%u_rel == res%u_rel) .and. all(res2%period_s == res%period_s))
        call write_text(SCR//'/bprime3.nml', BOX//'&design amplitude_max = 40 /'//NL)
        call read_deck(SCR//'/bprime3.nml', d, st)
        m = 0
        if (d%design%amplitude_measure == 25.0_dp) m = 1
        call write_text(SCR//'/bprime3.nml', BOX//'&design amplitude_max = 20 /'//NL)
        call read_deck(SCR//'/bprime3.nml', d, st)
        if (d%design%amplitude_measure == 20.0_dp) m = m + 1
        call t%check('b_prime: amplitude_measure defaults to min(25, amplitude_max)', m == 2)
    end subroutine test_b_prime

end module test_design
