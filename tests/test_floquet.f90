!> Tests of the Floquet analysis of pure torsion (stability, Figs. 13-16).
module test_floquet
    use kinds, only: dp, pi, deg
    use status, only: status_t, ERR_DECK
    use testing, only: tester_t
    use geometry, only: pendulum_t
    use bifilar_model, only: bifilar_t, chart_accelerations, chart_jacobian, NSTATE, &
                             chart_invariant_gradients, chart_constraint, chart_energy, &
                             chart_state
    use start_pose, only: raised_angles, solve_theta5
    use lsoda, only: lsoda_t, METHOD_BDF
    use ode_system, only: ode_system_t, integrator_stats_t
    use floquet, only: floquet_result_t, floquet_analysis, check_torsion_scene, torsion_period, &
                       jacobian_z, multipliers_from_monodromy, torsion_start, monodromy, &
                       pencil_multipliers, trivial_residual_of, GL_X, GL_W
    use paper_claims, only: rest_frequencies
    use lapack_wrap, only: la_eig, la_lu_factor, la_lu_solve
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of
    use test_model, only: torsion_1dof_t
    use rig, only: make_pendulum
    use unused_arg, only: unused
    implicit none
    private

    public :: run_floquet_tests

    real(dp), parameter :: A_BLOCK(2, 2) = reshape([-1000.0_dp, 0.0_dp, 999.0_dp, -1.0_dp], [2, 2])

    !> Three equal stiff 2 x 2 blocks; with structured = .true. the system factors and solves
    !! the stiff method's linear systems itself, block by block.
    type, extends(ode_system_t) :: blocks_t
        logical :: structured = .false.
        real(dp) :: lu(2, 2) = 0.0_dp
        integer :: ipiv(2) = 0
        integer :: solves = 0
    contains
        procedure :: rhs => blocks_rhs
        procedure :: jacobian => blocks_jacobian
        procedure :: has_jacobian => blocks_has_jacobian
        procedure :: has_iteration_solver => blocks_structured
        procedure :: factor_iteration => blocks_factor
        procedure :: solve_iteration => blocks_solve
    end type blocks_t

contains

    subroutine run_floquet_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        if (t%want('floquet: Gauss-Legendre table')) call test_gauss_table(t)
        if (t%want('floquet: period of pure torsion')) call test_period(t)
        if (t%want('floquet: the turning point by Newton = by the homotopy')) call test_start(t)
        if (t%want('floquet: Jacobian Z against directional differences')) call test_jacobian(t)
        if (t%want('floquet: exact Z against central differences, every column')) &
            call test_jacobian_columns(t)
        if (t%want('floquet: Z in one pass = Z by one tangent per column')) &
            call test_jacobian_one_pass(t)
        if (t%want('floquet: gradients of G, G'' and E against central differences')) &
            call test_invariant_gradients(t)
        if (t%want('floquet: structured iteration matrix = the integrator''s own')) &
            call test_structured_solve(t)
        if (t%want('floquet: small amplitude against the natural frequencies at rest')) &
            call test_small_amplitude(t)
        if (t%want('floquet: structure of the multipliers')) call test_structure(t)
        if (t%want('floquet: six columns N U0 = the whole half-period map')) &
            call test_six_columns(t)
        if (t%want('floquet: reciprocal partners up to modulus 1e6')) call test_pencil(t)
        if (t%want('floquet: finite differences of the nonlinear flow')) call test_flow_fd(t)
        if (t%want('floquet: half period by reversibility = whole period')) call test_half(t)
        if (t%want('floquet: a predicted instability is real')) call test_growth(t)
        if (t%want('floquet: scenes that are not pure torsion are refused')) &
            call test_refusal(t, exe)
        if (t%want('floquet: chart, serial and parallel')) call test_chart(t, exe)
    end subroutine run_floquet_tests

    function deck_pendulum(path) result(p)
        character(len=*), intent(in) :: path
        type(pendulum_t) :: p
        type(deck_t) :: d
        type(status_t) :: st
        call read_deck(path, d, st)
        call make_pendulum(rig_of(d), p, st)
        p%stab_rate = 0.0_dp
    end function deck_pendulum

    !> The 48-point Gauss-Legendre table of torsion_period: recomputed here in double
    !! precision (Newton on P_48 from the Chebyshev guess), and exact for x^k, k <= 95.
    subroutine test_gauss_table(t)
        type(tester_t), intent(inout) :: t
        real(dp) :: x(48), w(48)
        integer :: k
        logical :: ok
        call gauss_legendre(x, w)
        call t%check('Gauss-Legendre: nodes agree with the table to 4 ulp', &
            all(abs(x - GL_X) <= 4*epsilon(1.0_dp)))
        ! 1 - x^2 loses digits at the end nodes (1 - x^2 = 2.5e-3): the double-precision
        ! weights there are good to about eps/(1 - x^2)
        call t%check('Gauss-Legendre: weights agree with the table to 1e-12 relative', &
            all(abs(w - GL_W) <= 1.0e-12_dp*GL_W))
        ok = .true.
        do k = 0, 94, 2
            ok = ok .and. abs(sum(GL_W*GL_X**k) - 2.0_dp/(k + 1)) <= 1.0e-14_dp
            ok = ok .and. abs(sum(GL_W*GL_X**(k + 1))) <= 1.0e-15_dp
        end do
        call t%check('Gauss-Legendre: exact for x^k, k = 0 ... 95', ok)
    end subroutine test_gauss_table

    !> Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n from the Chebyshev guess).
    pure subroutine gauss_legendre(x, w)
        real(dp), intent(out) :: x(:), w(:)
        integer :: n, i, j, it
        real(dp) :: z, p0, p1, p2, dp_dz, dz
        n = size(x)
        do i = 1, n
            z = cos(pi*(i - 0.25_dp)/(n + 0.5_dp))
            do it = 1, 100
                p0 = 1.0_dp
                p1 = z
                do j = 2, n
                    p2 = ((2*j - 1)*z*p1 - (j - 1)*p0)/j
                    p0 = p1
                    p1 = p2
                end do
                dp_dz = n*(z*p1 - p0)/(z*z - 1.0_dp)
                dz = p1/dp_dz
                z = z - dz
                if (abs(dz) < 1.0e-16_dp) exit
            end do
            x(i) = z
            w(i) = 2.0_dp/((1.0_dp - z*z)*dp_dz**2)
        end do
    end subroutine gauss_legendre

    !> t* from the quadrature: the 1-DOF equations (45)-(48) integrated to t*/2 arrive at
    !! theta4 = -A at rest; at small amplitude t* = 4 pi sqrt(I1 l / (m g b^2)).
    subroutine test_period(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(torsion_1dof_t) :: one
        type(lsoda_t) :: s
        type(status_t) :: st
        real(dp) :: period, z(2)
        integer :: ivert
        call check_torsion_scene(p, ivert, st)
        call t%check('symmetric cylinder: vertical axis is b1', st%code == 0 .and. ivert == 1)
        call torsion_period(p, 45*deg, ivert, period, st)
        z = [45*deg, 0.0_dp]
        call s%init(one, 0.0_dp, z, 1.0e-13_dp, [1.0e-15_dp], st)
        call s%integrate(one, 0.5_dp*period, z, st)
        call t%check_close('t*/2 from quadrature: theta4 = -A', z(1), -45*deg, atol=1.0e-9_dp)
        call t%check_close('t*/2 from quadrature: at rest', z(2), 0.0_dp, atol=1.0e-9_dp)
        call torsion_period(p, 0.01_dp*deg, ivert, period, st)
        call t%check_close('small-amplitude t* = 4 pi sqrt(I1 l/(m g b^2))', period, &
                           4*pi*sqrt(p%inertia(1)*p%big_l), rtol=1.0e-8_dp)
        ! a tiny amplitude (&floquet amplitude = 1.97e-229 degrees: z(A) - z(q) underflowed
        ! to 0, SIGFPE in the checking build, found by the fuzz test): the same limit
        call torsion_period(p, 3.4e-231_dp, ivert, period, st)
        call t%check('tiny-amplitude t*: no failure', st%code == 0)
        call t%check_close('tiny-amplitude t* = 4 pi sqrt(I1 l/(m g b^2))', period, &
                           4*pi*sqrt(p%inertia(1)*p%big_l), rtol=1.0e-12_dp)
    end subroutine test_period

    !> torsion_start's theta_5 (Newton on eq. (2) from the raised pose) against start_pose's
    !! homotopy (solve_theta5), the whole chart state to 1e-14: the cylinder and the tall box
    !! with l' = l, and with l' = l (1 + 9e-7) (inside SYMMETRY_TOL, theta_5 /= 0), at 2, 45
    !! and 120 degrees.
    subroutine test_start(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(status_t) :: st, st2
        real(dp), parameter :: amps(3) = [2.0_dp, 45.0_dp, 120.0_dp]
        real(dp) :: y0(NSTATE), yh(NSTATE), th(5), e, amp
        integer :: ip, ia
        logical :: ok, moved
        e = 0.0_dp
        ok = .true.
        moved = .false.
        do ip = 1, 4
            p = deck_pendulum(trim(merge('input/cylinder_torsion.nml', &
                                         'input/box_tall_floquet.nml', ip <= 2)))
            if (mod(ip, 2) == 0) p%big_lp = p%big_l*(1.0_dp + 9.0e-7_dp)
            do ia = 1, 3
                amp = amps(ia)*deg
                call torsion_start(p, amp, y0, st)
                call raised_angles(p, amp, th, st2)
                if (st2%code == 0) call solve_theta5(p, th, st2)
                if (st%code /= 0 .or. st2%code /= 0) then
                    ok = ok .and. st%code == st2%code
                    cycle
                end if
                yh = chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp])
                e = max(e, maxval(abs(y0 - yh)))
                moved = moved .or. abs(y0(5)) > 1.0e-8_dp
            end do
        end do
        call t%check('torsion start: both ways succeed or fail alike; theta5 /= 0 met', &
                     ok .and. moved)
        call t%check_close('torsion start by Newton = by the homotopy (max norm)', e, 0.0_dp, &
                           atol=1.0e-14_dp)
    end subroutine test_start

    !> Z v against Richardson-extrapolated directional differences of the right-hand side:
    !! three general directions and each of Z's ten columns (the cable's own four take a
    !! shorter path through the kinematics' tangent).
    subroutine test_jacobian(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(status_t) :: st
        real(dp) :: y(NSTATE), v(NSTATE), z(NSTATE, NSTATE), d1(5), d2(5), ap(5), am(5), e
        real(dp) :: eps
        integer :: k, j
        p = deck_pendulum('input/box_unstable.nml')
        y = [0.02_dp, 0.1_dp, -0.05_dp, 0.4_dp, 0.03_dp, 0.1_dp, -0.2_dp, 0.15_dp, 0.5_dp, -0.1_dp]
        call jacobian_z(p, y, z, st)
        e = 0.0_dp
        do k = 1, 3 + NSTATE
            if (k <= 3) then
                v = [(sin(1.7_dp*k*(k + j)), j = 1, NSTATE)]
            else
                v = merge(1.0_dp, 0.0_dp, [(j == k - 3, j = 1, NSTATE)])
            end if
            eps = 1.0e-3_dp
            call chart_accelerations(p, y + eps*v, ap, st)
            call chart_accelerations(p, y - eps*v, am, st)
            d1 = (ap - am)/(2*eps)
            call chart_accelerations(p, y + 0.5_dp*eps*v, ap, st)
            call chart_accelerations(p, y - 0.5_dp*eps*v, am, st)
            d2 = (ap - am)/eps
            e = max(e, maxval(abs((4*d2 - d1)/3 - matmul(z(6:10, :), v))) &
                    /max(maxval(abs(matmul(z(6:10, :), v))), tiny(1.0_dp)))
        end do
        call t%check_close('Z v = directional derivative (relative), general directions '// &
                           'and each column', e, 0.0_dp, atol=1.0e-8_dp)
    end subroutine test_jacobian

    !> At small amplitude the multipliers tend to exp(+-2 pi i w_k / w_torsion), w_k the
    !! natural frequencies of the pendulum linearised at rest (eigenvalues by LAPACK).
    subroutine test_small_amplitude(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(floquet_result_t) :: r
        type(status_t) :: st
        real(dp) :: freq(5), ft, err, best
        complex(dp) :: pred
        integer :: nf, k, j, it
        call rest_frequencies(p, freq, nf, st)
        call t%check('four natural frequencies at rest', st%code == 0 .and. nf == 4)
        ! the torsion frequency: nearest to the bifilar formula 1/(4 pi sqrt(I1 l))
        ft = 1.0_dp/(4*pi*sqrt(p%inertia(1)*p%big_l))
        it = minloc(abs(freq(1:nf) - ft), 1)
        call t%check_close('torsion among the natural frequencies', freq(it), ft, rtol=1.0e-6_dp)
        call floquet_analysis(p, 0.2_dp*deg, 1.0e-11_dp, 1, r, st)
        call t%check('small-amplitude Floquet runs', st%code == 0)
        err = 0.0_dp
        do k = 1, nf
            if (k == it) cycle
            pred = exp(cmplx(0.0_dp, 2*pi*freq(k)/freq(it), dp))
            best = huge(1.0_dp)
            do j = 1, 6
                best = min(best, abs(r%multipliers(j) - pred), abs(r%multipliers(j) - conjg(pred)))
            end do
            err = max(err, best)
        end do
        call t%check_close('multipliers -> exp(+-2 pi i w_k/w_t) at 0.2 deg', err, 0.0_dp, &
                           atol=1.0e-4_dp)
    end subroutine test_small_amplitude

    !> The eigen-solve alone at moduli up to 1e6: a reversible half-period map with known
    !! multipliers exp(+-2s) = 1e6, 1e-6 (hyperbolic), exp(+-2i phi) (elliptic) and 1e3, 1e-3,
    !! hidden by random orthogonal changes of basis at both ends.  The pencil gives every
    !! multiplier to 1e-9 relative and the reciprocal pairs to 1e-6; the explicit product
    !! would lose the small partner (its error is reported for comparison).
    subroutine test_pencil(t)
        type(tester_t), intent(inout) :: t
        real(dp) :: n(6, 6), r(6, 6), v0(6, 6), vh(6, 6), nn(6, 6), r0(6, 6), rh(6, 6), s1, s2, ph
        real(dp) :: lu(6, 6), x(6), ninv(6, 6), m(6, 6), e, eprod
        complex(dp) :: lam(6), exact(6), lp(6)
        type(status_t) :: st
        integer :: k, j, ipiv(6)
        s1 = 0.5_dp*log(1.0e6_dp)      ! exp(2 s1) = 1e6
        s2 = 0.5_dp*log(1.0e3_dp)
        ph = 0.7_dp
        ! coordinates (q1, q2, q3, p1, p2, p3); R = diag(1, 1, 1, -1, -1, -1)
        n = 0.0_dp
        r = 0.0_dp
        do k = 1, 3
            r(k, k) = 1.0_dp
            r(k + 3, k + 3) = -1.0_dp
        end do
        call block(1, cosh(s1), sinh(s1), sinh(s1), cosh(s1))
        call block(2, cosh(s2), sinh(s2), sinh(s2), cosh(s2))
        call block(3, cos(ph), sin(ph), -sin(ph), cos(ph))
        exact = [cmplx(1.0e6_dp, 0.0_dp, dp), cmplx(1.0e3_dp, 0.0_dp, dp), &
                 exp(cmplx(0.0_dp, 2*ph, dp)), exp(cmplx(0.0_dp, -2*ph, dp)), &
                 cmplx(1.0e-3_dp, 0.0_dp, dp), cmplx(1.0e-6_dp, 0.0_dp, dp)]
        call random_orthogonal(v0, 3)
        call random_orthogonal(vh, 7)
        nn = matmul(vh, matmul(n, transpose(v0)))
        r0 = matmul(v0, matmul(r, transpose(v0)))
        rh = matmul(vh, matmul(r, transpose(vh)))
        call pencil_multipliers(nn, r0, rh, lam, st)
        call t%check('pencil QZ runs', st%code == 0)
        e = 0.0_dp
        do k = 1, 6
            e = max(e, minval(abs(lam - exact(k)))/abs(exact(k)))
        end do
        call t%check_close('every multiplier to 1e-9 relative (1e6 ... 1e-6)', e, 0.0_dp, &
                           atol=1.0e-9_dp)
        call t%check_close('reciprocal pair 1e6 * 1e-6', abs(lam(1)*lam(6)), 1.0_dp, &
                           atol=1.0e-6_dp)
        ! the explicit product for comparison
        lu = nn
        call la_lu_factor(lu, ipiv, st)
        do j = 1, 6
            x = 0.0_dp
            x(j) = 1.0_dp
            call la_lu_solve(lu, ipiv, x, st)
            ninv(:, j) = x
        end do
        m = matmul(r0, matmul(ninv, matmul(rh, nn)))
        call la_eig(m, lp, st)
        eprod = abs(minval(abs(lp))*1.0e6_dp - 1.0_dp)
        write (*, '(a,es9.2,a,es9.2)') '   reciprocal-pair error at 1e6: pencil ', &
            abs(abs(lam(1)*lam(6)) - 1.0_dp), ', explicit product + dgeev ', eprod
    contains
        subroutine block(i, a11, a12, a21, a22)
            integer, intent(in) :: i
            real(dp), intent(in) :: a11, a12, a21, a22
            n(i, i) = a11
            n(i, i + 3) = a12
            n(i + 3, i) = a21
            n(i + 3, i + 3) = a22
        end subroutine block
    end subroutine test_pencil

    !> A reproducible random orthogonal matrix: Gram-Schmidt (twice) of a matrix filled by a
    !! hash of the indices (fractional part of a scaled sine, full rank).
    subroutine random_orthogonal(q, seed)
        real(dp), intent(out) :: q(:, :)
        integer, intent(in) :: seed
        integer :: i, j, k, pass
        do j = 1, size(q, 2)
            do i = 1, size(q, 1)
                q(i, j) = modulo(43758.5453_dp*sin(real(37*i + 101*j + 7*seed, dp)), 1.0_dp) &
                          - 0.5_dp
            end do
            do pass = 1, 2
                do k = 1, j - 1
                    q(:, j) = q(:, j) - dot_product(q(:, k), q(:, j))*q(:, k)
                end do
            end do
            q(:, j) = q(:, j)/norm2(q(:, j))
        end do
    end subroutine random_orthogonal

    !> A small chart through the executable: the same file with 1 and 2 OpenMP threads, one
    !! row per grid point, stable and unstable points both present, no NaN.
    subroutine test_chart(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: dir = 'build/test_floquet'
        integer :: ex1, ex2, exc, u, ios, rows, nst, nun
        real(dp) :: v(4)
        character(len=512) :: line
        call execute_command_line('mkdir -p '//dir//'/c1 '//dir//'/c2 && sed -e '// &
            '"s/nx = 60/nx = 5/" -e "s/ny = 45/ny = 4/" -e "s/x_max = 8.0/x_max = 4.0/" '// &
            'input/box_chart.nml > '//dir//'/chart_small.nml')
        call execute_command_line('OMP_NUM_THREADS=1 '//exe//' '//dir//'/chart_small.nml --out '// &
                                  dir//'/c1 > /dev/null 2>&1', exitstat=ex1)
        call execute_command_line('OMP_NUM_THREADS=2 '//exe//' '//dir//'/chart_small.nml --out '// &
                                  dir//'/c2 > /dev/null 2>&1', exitstat=ex2)
        call t%check('chart runs with 1 and 2 threads', ex1 == 0 .and. ex2 == 0)
        call execute_command_line('cmp -s '//dir//'/c1/chart_small.chart.dat '//dir// &
                                  '/c2/chart_small.chart.dat', exitstat=exc)
        call t%check('chart: 1 and 2 threads give the same file', exc == 0)
        rows = 0
        nst = 0
        nun = 0
        open (newunit=u, file=dir//'/c2/chart_small.chart.dat', status='old', action='read', &
              iostat=ios)
        do while (ios == 0)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
            read (line, *, iostat=ios) v
            if (ios /= 0) exit
            if (.not. all(abs(v) < huge(1.0_dp))) exit
            rows = rows + 1
            if (v(3) >= 0.0_dp .and. v(3) <= 1.0_dp + 1.0e-6_dp) nst = nst + 1
            if (v(3) > 1.0_dp + 1.0e-6_dp) nun = nun + 1
        end do
        call t%check('chart: 20 finite rows', rows == 20)
        call t%check('chart: stable and unstable points both found', nst > 0 .and. nun > 0)
    end subroutine test_chart

    !> Reciprocal pairs, trivial multipliers, product 1 for the cylinder and both boxes.
    subroutine test_structure(t)
        type(tester_t), intent(inout) :: t
        character(len=40), parameter :: decks(3) = [character(len=40) :: &
            'input/cylinder_torsion.nml', 'input/box_stable.nml', 'input/box_tall_floquet.nml']
        type(pendulum_t) :: p
        type(floquet_result_t) :: r, rw
        type(status_t) :: st
        real(dp) :: worst, pr
        integer :: k, i, j
        do k = 1, size(decks)
            p = deck_pendulum(trim(decks(k)))
            ! integration error is amplified by the largest modulus (2.65e3 for box_tall)
            call floquet_analysis(p, 45*deg, merge(1.0e-12_dp, 1.0e-10_dp, k == 3), 1, r, st)
            call t%check(trim(decks(k))//': analysis runs', st%code == 0)
            ! each multiplier has a partner with lambda * partner = 1 (partner = 1/lambda or
            ! the conjugate of 1/lambda for a pair on the unit circle)
            worst = 0.0_dp
            do i = 1, 6
                pr = huge(1.0_dp)
                do j = 1, 6
                    if (j /= i) pr = min(pr, abs(r%multipliers(i)*r%multipliers(j) - 1.0_dp), &
                                         abs(r%multipliers(i)*conjg(r%multipliers(j)) - 1.0_dp))
                end do
                worst = max(worst, pr)
            end do
            call t%check_close(trim(decks(k))//': reciprocal pairs', worst, 0.0_dp, &
                               atol=1.0e-6_dp)
            call t%check_close(trim(decks(k))//': trivial multipliers are 1 (identities)', &
                               r%trivial_residual, 0.0_dp, atol=1.0e-6_dp)
            call t%check_close(trim(decks(k))//': product of all multipliers', &
                               abs(product(r%multipliers)), 1.0_dp, atol=1.0e-6_dp)
            call floquet_analysis(p, 45*deg, merge(1.0e-12_dp, 1.0e-10_dp, k == 3), 1, rw, st, &
                                  whole_map=.true.)
            call t%check(trim(decks(k))//': analysis of the whole map runs', st%code == 0)
            call t%check_close(trim(decks(k))//': det H(t*) = 1 (Liouville)', &
                               det10(rw%monodromy), 1.0_dp, atol=1.0e-6_dp)
            call t%check_close(trim(decks(k))//': orbit closes', r%orbit_closure, 0.0_dp, &
                               atol=1.0e-8_dp)
        end do
        call t%check('cylinder stable', .true. .eqv. stable_of('input/cylinder_torsion.nml'))
        call t%check('box_stable stable', stable_of('input/box_stable.nml'))
        call t%check('box_tall unstable, of the paper''s order (1e3)', &
                     .not. stable_of('input/box_tall_floquet.nml') .and. r%max_modulus > 1.0e3_dp)
    end subroutine test_structure

    !> The default analysis integrates six columns of the half-period map, N U0; the one of
    !! the whole map (all ten columns, whole_map) gives the same multipliers within 1e-8
    !! (relative to max(1, |lambda|)), at 45 deg, rtol 1e-10, for the cylinder, both boxes of
    !! Figs. 13-16 and the tall box (modulus 2.65e3).  The trivial identities hold on both
    !! computed maps to 1e-8; the residual measures them (a map off the subspace, N U0 with a
    !! part along grad G at t*/2, is caught).
    subroutine test_six_columns(t)
        type(tester_t), intent(inout) :: t
        character(len=40), parameter :: decks(4) = [character(len=40) :: &
            'input/cylinder_torsion.nml', 'input/box_stable.nml', 'input/box_unstable.nml', &
            'input/box_tall_floquet.nml']
        type(floquet_result_t) :: r6, rw
        type(status_t) :: st, stw
        real(dp) :: rows(NSTATE, 3), nu(NSTATE, 6), q(NSTATE, NSTATE), e
        integer :: k, i, j
        do k = 1, size(decks)
            call floquet_analysis(deck_pendulum(trim(decks(k))), 45*deg, 1.0e-10_dp, 1, r6, st)
            call floquet_analysis(deck_pendulum(trim(decks(k))), 45*deg, 1.0e-10_dp, 1, rw, &
                                  stw, whole_map=.true.)
            call t%check(trim(decks(k))//': six columns and the whole map both run', &
                         st%code == 0 .and. stw%code == 0)
            e = 0.0_dp
            do i = 1, 6
                e = max(e, minval(abs(rw%multipliers(1:6) - r6%multipliers(i))) &
                        /max(1.0_dp, abs(r6%multipliers(i))))
                e = max(e, minval(abs(r6%multipliers(1:6) - rw%multipliers(i))) &
                        /max(1.0_dp, abs(rw%multipliers(i))))
            end do
            call t%check_close(trim(decks(k))//': six columns = whole map, multipliers', &
                               e, 0.0_dp, atol=1.0e-8_dp)
            call t%check_close(trim(decks(k))//': six columns = whole map, largest modulus', &
                               r6%max_modulus, rw%max_modulus, rtol=1.0e-8_dp)
            call t%check(trim(decks(k))//': trivial identities on both maps within 1e-8', &
                         r6%trivial_residual < 1.0e-8_dp .and. rw%trivial_residual < 1.0e-8_dp)
            call t%check(trim(decks(k))//': the same four trivial multipliers, 1', &
                         all(r6%trivial .eqv. rw%trivial) .and. count(r6%trivial) == 4 .and. &
                         all(r6%multipliers(7:10) == (1.0_dp, 0.0_dp)))
            call t%check(trim(decks(k))//': the monodromy only with the whole map', &
                         all(r6%monodromy == 0.0_dp) .and. any(rw%monodromy /= 0.0_dp))
        end do
        ! the residual: columns orthogonal to the three gradients give roundoff, a part along
        ! grad G of 1e-6 of a column gives 1e-6
        do j = 1, NSTATE
            do i = 1, NSTATE
                q(i, j) = sin(1.3_dp*i + 0.7_dp*j*j)
            end do
        end do
        call orthonormalise(q)
        rows = 3.0_dp*q(:, 1:3)
        nu = 2.0_dp*q(:, 4:9)
        call t%check_close('trivial residual of a map on the subspace: roundoff', &
                           trivial_residual_of(rows, nu), 0.0_dp, atol=1.0e-14_dp)
        nu(:, 2) = nu(:, 2) + 1.0e-6_dp*norm2(nu)*q(:, 1)
        call t%check_close('trivial residual of a map off it: its part along grad G', &
                           trivial_residual_of(rows, nu), 1.0e-6_dp, rtol=1.0e-6_dp)
    end subroutine test_six_columns

    !> The columns of q made orthonormal, in order (modified Gram-Schmidt, twice).
    pure subroutine orthonormalise(q)
        real(dp), intent(inout) :: q(:, :)
        integer :: j, i, pass
        do j = 1, size(q, 2)
            do pass = 1, 2
                do i = 1, j - 1
                    q(:, j) = q(:, j) - dot_product(q(:, i), q(:, j))*q(:, i)
                end do
            end do
            q(:, j) = q(:, j)/norm2(q(:, j))
        end do
    end subroutine orthonormalise

    logical function stable_of(path)
        character(len=*), intent(in) :: path
        type(floquet_result_t) :: r
        type(status_t) :: st
        call floquet_analysis(deck_pendulum(path), 45*deg, 1.0e-10_dp, 1, r, st)
        stable_of = r%stable .and. st%code == 0
    end function stable_of

    !> Determinant of a 10 x 10 matrix by Gaussian elimination with partial pivoting.
    real(dp) function det10(a) result(det)
        real(dp), intent(in) :: a(NSTATE, NSTATE)
        real(dp) :: m(NSTATE, NSTATE), row(NSTATE)
        integer :: i, k, piv
        m = a
        det = 1.0_dp
        do k = 1, NSTATE
            piv = maxloc(abs(m(k:, k)), 1) + k - 1
            if (piv /= k) then
                row = m(k, :); m(k, :) = m(piv, :); m(piv, :) = row
                det = -det
            end if
            det = det*m(k, k)
            do i = k + 1, NSTATE
                m(i, k:) = m(i, k:) - m(i, k)/m(k, k)*m(k, k:)
            end do
        end do
    end function det10

    !> The monodromy by finite differences of the full nonlinear flow over one period gives
    !! the same multipliers as the variational equations.
    subroutine test_flow_fd(t)
        type(tester_t), intent(inout) :: t
        type(bifilar_t) :: sys
        type(floquet_result_t) :: r, rfd
        type(lsoda_t) :: s
        type(status_t) :: st
        real(dp) :: y0(NSTATE), yp(NSTATE), ym(NSTATE), h(NSTATE, NSTATE), eps, err
        integer :: j, k
        sys%p = deck_pendulum('input/box_unstable.nml')
        call floquet_analysis(sys%p, 45*deg, 1.0e-11_dp, 1, r, st)
        call torsion_start(sys%p, 45*deg, y0, st)
        do j = 1, NSTATE
            eps = 1.0e-5_dp
            yp = y0
            yp(j) = yp(j) + eps
            call s%init(sys, 0.0_dp, yp, 1.0e-12_dp, [1.0e-14_dp], st)
            call s%integrate(sys, r%period, yp, st)
            ym = y0
            ym(j) = ym(j) - eps
            call s%init(sys, 0.0_dp, ym, 1.0e-12_dp, [1.0e-14_dp], st)
            call s%integrate(sys, r%period, ym, st)
            h(:, j) = (yp - ym)/(2*eps)
        end do
        call t%check('nonlinear flow integrates', st%code == 0)
        rfd = r
        call multipliers_from_monodromy(sys%p, y0, r%period, h, rfd, st)
        err = 0.0_dp
        do k = 1, 6
            err = max(err, minval(abs(rfd%multipliers(1:6) - r%multipliers(k))) &
                      /max(1.0_dp, abs(r%multipliers(k))))
        end do
        call t%check_close('multipliers from flow differences = variational', err, 0.0_dp, &
                           atol=1.0e-5_dp)
        call t%check_close('largest multiplier from flow differences', rfd%max_modulus, &
                           r%max_modulus, rtol=1.0e-5_dp)
    end subroutine test_flow_fd

    !> The monodromy from half a period and the reversibility of the equations equals the one
    !! integrated over the whole period, in several shooting segments.
    subroutine test_half(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(floquet_result_t) :: r
        type(status_t) :: st
        real(dp) :: y0(NSTATE), yend(NSTATE), hfull(NSTATE, NSTATE), hhalf(NSTATE, NSTATE)
        integer :: ns, nr
        p = deck_pendulum('input/box_unstable.nml')
        call floquet_analysis(p, 45*deg, 1.0e-11_dp, 1, r, st)
        call torsion_start(p, 45*deg, y0, st)
        call monodromy(p, y0, r%period, 4, 1.0e-11_dp, hfull, yend, ns, nr, st, full=.true.)
        call t%check('whole period in 4 segments integrates', st%code == 0)
        call t%check_close('whole period closes the orbit', maxval(abs(yend - y0)), 0.0_dp, &
                           atol=1.0e-8_dp)
        call monodromy(p, y0, r%period, 1, 1.0e-11_dp, hhalf, yend, ns, nr, st)
        call t%check_close('H(t*) by reversibility = H(t*) integrated (relative)', &
                           maxval(abs(hfull - hhalf))/maxval(abs(hfull)), 0.0_dp, atol=1.0e-7_dp)
    end subroutine test_half

    !> The unstable deck: a tiny tilt on pure torsion grows by the largest multiplier each
    !! period (early, linear phase); the stable deck's tilt stays small.
    subroutine test_growth(t)
        type(tester_t), intent(inout) :: t
        type(bifilar_t) :: sys, ref
        type(floquet_result_t) :: r
        type(lsoda_t) :: s, s0
        type(status_t) :: st
        real(dp) :: y(NSTATE), y0(NSTATE), dev(0:3), tmax
        integer :: k
        sys%p = deck_pendulum('input/box_unstable.nml')
        ref%p = sys%p
        call floquet_analysis(sys%p, 45*deg, 1.0e-10_dp, 1, r, st)
        call torsion_start(sys%p, 45*deg, y0, st)
        y = y0
        y(1) = 1.0e-9_dp
        call s%init(sys, 0.0_dp, y, 1.0e-12_dp, [1.0e-16_dp], st)
        call s0%init(ref, 0.0_dp, y0, 1.0e-12_dp, [1.0e-16_dp], st)
        dev(0) = 1.0e-9_dp
        do k = 1, 3
            call s%integrate(sys, k*r%period, y, st)
            call s0%integrate(ref, k*r%period, y0, st)
            dev(k) = maxval(abs(y - y0))
        end do
        call t%check_close('unstable: growth per period = largest multiplier (3rd period)', &
                           dev(3)/dev(2), r%max_modulus, rtol=0.05_dp)
        ! stable deck: theta1 from 0.01 rad stays below 0.02 over 5 periods
        sys%p = deck_pendulum('input/box_stable.nml')
        call floquet_analysis(sys%p, 45*deg, 1.0e-10_dp, 1, r, st)
        call torsion_start(sys%p, 45*deg, y, st)
        y(1) = 0.01_dp
        call s%init(sys, 0.0_dp, y, 1.0e-10_dp, [1.0e-12_dp], st)
        tmax = 0.0_dp
        do k = 1, 500
            call s%integrate(sys, k*5*r%period/500, y, st)
            tmax = max(tmax, abs(y(1)))
        end do
        call t%check('stable: tilt from 0.01 rad stays below 0.02 rad for 5 periods', &
                     st%code == 0 .and. tmax < 0.02_dp)
    end subroutine test_growth

    !> Decks where pure torsion is not an exact motion are refused, naming the condition.
    subroutine test_refusal(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        type(pendulum_t) :: p
        type(status_t) :: st
        integer :: ivert, ex
        p%big_lp = 1.8_dp
        call check_torsion_scene(p, ivert, st)
        call t%check('unequal cables refused', st%code == ERR_DECK .and. &
                     index(st%msg, 'equal cables') > 0)
        p = pendulum_t()
        p%lambda = 0.5_dp
        call check_torsion_scene(p, ivert, st)
        call t%check('mass centre off the bisector refused', st%code == ERR_DECK .and. &
                     index(st%msg, 'bisector') > 0)
        p = pendulum_t()
        p%btilde = reshape([-1.0_dp, -1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, sqrt(2.0_dp), &
                            -1.0_dp, 1.0_dp, 0.0_dp], [3, 3])/sqrt(2.0_dp)
        call check_torsion_scene(p, ivert, st)
        call t%check('no vertical principal axis refused', st%code == ERR_DECK .and. &
                     index(st%msg, 'principal axis') > 0)
        call execute_command_line('mkdir -p build/test_floquet && sed "s/analyses = '// &
            '''simulate''/analyses = ''floquet''/" input/cylinder_l180.nml > '// &
            'build/test_floquet/unequal.nml')
        call execute_command_line(exe//' build/test_floquet/unequal.nml --out '// &
                                  'build/test_floquet > /dev/null 2>&1', exitstat=ex)
        call t%check('floquet on unequal cables: exit 2', ex == ERR_DECK)
    end subroutine test_refusal

    !> Every column of the exact Z (eq. (51)) against fourth-order central differences of the
    !! accelerations (h = 1e-4 max(1, |y_j|): truncation ~1e-16, rounding ~1e-12), at generic
    !! states of three pendulums: the box, the cylinder with Baumgarte's terms (the form the
    !! simulations integrate), the triangular plate with its principal axes off ntilde.
    subroutine test_jacobian_columns(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(status_t) :: st
        real(dp) :: y(NSTATE), z(NSTATE, NSTATE), a(5, -2:2), fd(5), h, e, zmax
        integer :: ip, is, j, m
        logical :: ok
        e = 0.0_dp
        ok = .true.
        do ip = 1, 3
            select case (ip)
            case (1)
                p = deck_pendulum('input/box_unstable.nml')
            case (2)
                p = deck_pendulum('input/cylinder_l180.nml')
                p%stab_rate = 1.0_dp
            case default
                p = deck_pendulum('input/triangle_plate.nml')
            end select
            do is = 1, 3
                y = [0.02_dp, 0.1_dp, -0.05_dp, 0.4_dp, 0.03_dp, 0.1_dp, -0.2_dp, 0.15_dp, &
                     0.5_dp, -0.1_dp]*is
                call jacobian_z(p, y, z, st)
                ok = ok .and. st%code == 0
                zmax = max(1.0_dp, maxval(abs(z)))
                do j = 1, NSTATE
                    h = 1.0e-4_dp*max(1.0_dp, abs(y(j)))
                    do m = -2, 2
                        if (m == 0) cycle
                        call chart_accelerations(p, y + m*h*unit10(j), a(:, m), st)
                        ok = ok .and. st%code == 0
                    end do
                    fd = (8*(a(:, 1) - a(:, -1)) - (a(:, 2) - a(:, -2)))/(12*h)
                    e = max(e, maxval(abs(fd - z(6:10, j)))/zmax)
                    ok = ok .and. all(z(1:5, j) == merge(1.0_dp, 0.0_dp, [(m + 5 == j, m=1, 5)]))
                end do
            end do
        end do
        call t%check('Z: upper half (0 I), every evaluation succeeds', ok)
        call t%check_close('Z: every column = central differences (relative to max |Z|)', e, &
                           0.0_dp, atol=1.0e-8_dp)
    end subroutine test_jacobian_columns

    !> Z in one pass (chart_jacobian's default, bifilar_model's jacobian_columns) against Z
    !! by one kinematic tangent and eom_tangent per column (the single-direction path),
    !! every entry to roundoff (1e-13 of max |Z|): the box, the cylinder with Baumgarte's
    !! terms, the cylinder damped (linear and quadratic), the triangular plate with its
    !! principal axes off ntilde, the tall box; at rest and at three generic states.
    subroutine test_jacobian_one_pass(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(status_t) :: st, st2
        real(dp) :: y(NSTATE), z1(NSTATE, NSTATE), z2(NSTATE, NSTATE), qdd(5), e
        integer :: ip, is
        logical :: ok
        e = 0.0_dp
        ok = .true.
        do ip = 1, 5
            select case (ip)
            case (1)
                p = deck_pendulum('input/box_unstable.nml')
            case (2)
                p = deck_pendulum('input/cylinder_l180.nml')
                p%stab_rate = 1.3_dp
            case (3)
                p = deck_pendulum('input/cylinder_l180.nml')
                p%c_v = 0.03_dp
                p%c_q = 0.02_dp
            case (4)
                p = deck_pendulum('input/triangle_plate.nml')
            case default
                p = deck_pendulum('input/box_tall_floquet.nml')
            end select
            do is = 0, 3
                y = [0.02_dp, 0.1_dp, -0.05_dp, 0.4_dp, 0.03_dp, 0.1_dp, -0.2_dp, 0.15_dp, &
                     0.5_dp, -0.1_dp]*is
                y(4) = y(4) + 0.3_dp
                call chart_jacobian(p, y, qdd, z1, st)
                call chart_jacobian(p, y, qdd, z2, st2, tangents=.true.)
                ok = ok .and. st%code == 0 .and. st2%code == 0
                e = max(e, maxval(abs(z1 - z2))/maxval(abs(z2)))
            end do
        end do
        call t%check('Z in one pass and by tangents: every evaluation succeeds', ok)
        call t%check_close('Z in one pass = Z by tangents, every entry (relative to max |Z|)', &
                           e, 0.0_dp, atol=1.0e-13_dp)
    end subroutine test_jacobian_one_pass

    !> The exact gradients of the constraint G, its rate G' and the energy E
    !! (chart_invariant_gradients, the rows of the reduction to S) against fourth-order central
    !! differences of chart_constraint and chart_energy (h = 1e-3 max(1, |y_j|): error about
    !! 1e-12), every component, relative to the largest of its gradient: the box, the
    !! cylinder, the triangular plate, the tall box, at a turning point of the torsion and at
    !! generic states.
    subroutine test_invariant_gradients(t)
        type(tester_t), intent(inout) :: t
        type(pendulum_t) :: p
        type(status_t) :: st
        real(dp) :: y(NSTATE), rows(NSTATE, 3), fd(NSTATE, 3), v(3, -2:2), h, e
        integer :: ip, is, j, m
        e = 0.0_dp
        do ip = 1, 4
            select case (ip)
            case (1)
                p = deck_pendulum('input/box_unstable.nml')
            case (2)
                p = deck_pendulum('input/cylinder_l180.nml')
            case (3)
                p = deck_pendulum('input/triangle_plate.nml')
            case default
                p = deck_pendulum('input/box_tall_floquet.nml')
            end select
            do is = 0, 3
                if (is == 0) then
                    call torsion_start(deck_pendulum('input/box_unstable.nml'), 45*deg, y, st)
                else
                    y = [0.02_dp, 0.1_dp, -0.05_dp, 0.4_dp, 0.03_dp, 0.1_dp, -0.2_dp, &
                         0.15_dp, 0.5_dp, -0.1_dp]*is
                end if
                call chart_invariant_gradients(p, y, rows)
                do j = 1, NSTATE
                    h = 1.0e-3_dp*max(1.0_dp, abs(y(j)))
                    do m = -2, 2
                        if (m == 0) cycle
                        call chart_constraint(p, y + m*h*unit10(j), v(1, m), v(2, m))
                        v(3, m) = chart_energy(p, y + m*h*unit10(j))
                    end do
                    fd(j, :) = (8*(v(:, 1) - v(:, -1)) - (v(:, 2) - v(:, -2)))/(12*h)
                end do
                do m = 1, 3
                    e = max(e, maxval(abs(rows(:, m) - fd(:, m)))/maxval(abs(fd(:, m))))
                end do
            end do
        end do
        call t%check_close('grad G, grad G'', grad E = central differences (relative)', e, &
                           0.0_dp, atol=1.0e-9_dp)
    end subroutine test_invariant_gradients

    pure function unit10(j) result(v)
        integer, intent(in) :: j
        real(dp) :: v(NSTATE)
        v = 0.0_dp
        v(j) = 1.0_dp
    end function unit10

    !> The integrator's structured iteration matrix (ode_system's has_iteration_solver): a
    !! stiff linear system of three equal 2 x 2 blocks integrated with the integrator's own
    !! 6 x 6 LU of I - h l0 J and with the system's 2 x 2 factor and block solves: the same
    !! steps, evaluations, Jacobians and factorisations, the same solution to roundoff, and
    !! BDF in use (so the solves were the system's).
    subroutine test_structured_solve(t)
        type(tester_t), intent(inout) :: t
        type(blocks_t) :: dense, structured
        type(lsoda_t) :: s1, s2
        type(integrator_stats_t) :: st1, st2
        type(status_t) :: e1, e2
        real(dp) :: y1(6), y2(6)
        structured%structured = .true.
        y1 = [1.0_dp, 0.0_dp, 0.5_dp, 1.0_dp, -1.0_dp, 2.0_dp]
        y2 = y1
        call s1%init(dense, 0.0_dp, y1, 1.0e-7_dp, [1.0e-9_dp], e1)
        call s1%integrate(dense, 20.0_dp, y1, e1)
        call s2%init(structured, 0.0_dp, y2, 1.0e-7_dp, [1.0e-9_dp], e2)
        call s2%integrate(structured, 20.0_dp, y2, e2)
        st1 = s1%stats()
        st2 = s2%stats()
        call t%check('both integrate', e1%code == 0 .and. e2%code == 0)
        call t%check('stiff: BDF, Jacobians and factorisations used', &
                     st2%method_last == METHOD_BDF .and. st2%jac_evals > 0 .and. &
                     st2%lu_decomps > 0 .and. structured%solves > 0)
        call t%check('same steps, rhs, Jacobians, factorisations, switches', &
                     st1%steps == st2%steps .and. st1%rhs_evals == st2%rhs_evals .and. &
                     st1%jac_evals == st2%jac_evals .and. st1%lu_decomps == st2%lu_decomps .and. &
                     st1%method_switches == st2%method_switches)
        call t%check_close('same solution (relative)', maxval(abs(y1 - y2))/maxval(abs(y1)), &
                           0.0_dp, atol=1.0e-12_dp)
    end subroutine test_structured_solve

    !> y' = diag(A, A, A) y, A = [[-1000, 999], [0, -1]]: stiff.
    subroutine blocks_rhs(sys, t, y, ydot, stat)
        class(blocks_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        integer :: c
        call unused(sys)
        call unused(t)
        do c = 0, 2
            ydot(2*c + 1:2*c + 2) = matmul(A_BLOCK, y(2*c + 1:2*c + 2))
        end do
        stat%code = 0
    end subroutine blocks_rhs

    subroutine blocks_jacobian(sys, t, y, dfdy, stat)
        class(blocks_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        integer :: c
        call unused(sys)
        call unused(t)
        call unused(y)
        dfdy = 0.0_dp
        do c = 0, 2
            dfdy(2*c + 1:2*c + 2, 2*c + 1:2*c + 2) = A_BLOCK
        end do
        stat%code = 0
    end subroutine blocks_jacobian

    logical function blocks_has_jacobian(sys)
        class(blocks_t), intent(in) :: sys
        blocks_has_jacobian = .true. .or. sys%structured
    end function blocks_has_jacobian

    logical function blocks_structured(sys)
        class(blocks_t), intent(in) :: sys
        blocks_structured = sys%structured
    end function blocks_structured

    subroutine blocks_factor(sys, t, y, hl0, rewt, jnorm, singular, stat)
        class(blocks_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:), hl0, rewt(:)
        real(dp), intent(out) :: jnorm
        logical, intent(out) :: singular
        type(status_t), intent(out) :: stat
        type(status_t) :: lst
        real(dp) :: rowsum
        integer :: c, i
        call unused(t)
        call unused(y)
        jnorm = 0.0_dp
        do c = 0, 2
            do i = 1, 2
                rowsum = abs(A_BLOCK(i, 1))/rewt(2*c + 1) + abs(A_BLOCK(i, 2))/rewt(2*c + 2)
                jnorm = max(jnorm, rowsum*rewt(2*c + i))
            end do
        end do
        sys%lu = -hl0*A_BLOCK
        sys%lu(1, 1) = sys%lu(1, 1) + 1.0_dp
        sys%lu(2, 2) = sys%lu(2, 2) + 1.0_dp
        call la_lu_factor(sys%lu, sys%ipiv, lst)
        singular = lst%code /= 0
        stat%code = 0
    end subroutine blocks_factor

    subroutine blocks_solve(sys, x, stat)
        class(blocks_t), intent(inout) :: sys
        real(dp), intent(inout) :: x(:)
        type(status_t), intent(out) :: stat
        real(dp) :: b(2)
        integer :: c
        sys%solves = sys%solves + 1
        do c = 0, 2
            b = x(2*c + 1:2*c + 2)
            call la_lu_solve(sys%lu, sys%ipiv, b, stat)
            x(2*c + 1:2*c + 2) = b
        end do
    end subroutine blocks_solve

end module test_floquet
