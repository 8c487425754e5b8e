!> Tests of module radau (Radau IIA of order 5): its coefficients against the published
!! values, exactness of the collocation polynomial, the seven standard problems of the
!! anchors (shared/reference/integrator), a lightly damped stiff oscillation beside a slow
!! forced mode, and the failure paths; the argument checks integrator_t makes for both
!! integrators, LSODA's and Radau's alike.
module test_radau
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK
    use ode_system, only: ode_system_t, integrator_t, integrator_stats_t
    use radau, only: radau_t, radau_coeffs_t, radau_coefficients
    use integrators, only: new_integrator, SOLVER_LSODA, SOLVER_RADAU
    use status, only: RADAU_ERR_ILLEGAL_INPUT, RADAU_ERR_TOO_MUCH_ACCURACY, RADAU_ERR_MAX_STEPS, &
        LSODA_ERR_ILLEGAL_INPUT, LSODA_ERR_MAX_STEPS
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    use test_lsoda, only: bench_problem, scaled_error, NBENCH, BENCH_NAMES
    use testing, only: tester_t
    use unused_arg, only: unused
    implicit none
    private

    public :: run_radau_tests, radau_on_grid

    !> y' = 3 t^2 + 2 t (y = t^3 + t^2 + y0): a cubic, which collocation of degree 3 reproduces.
    type, extends(ode_system_t) :: cubic_t
    contains
        procedure :: rhs => cubic_rhs
    end type cubic_t

    !> A lightly damped stiff oscillation x driven by a slow forced oscillator z:
    !!   x' = A x + w (z, 0),  A = [[-e, w], [-w, -e]]  (eigenvalues -e +- i w),
    !!   z'' + z = cos(nu t)                            (the slow mode; y = (x1, x2, z, z')).
    type, extends(ode_system_t) :: stiff_osc_t
        real(dp) :: e = 10.0_dp, w = 1.0e4_dp, nu = 0.5_dp
    contains
        procedure :: rhs => osc_rhs
        procedure :: jacobian => osc_jac
        procedure :: has_jacobian => osc_has_jac
    end type stiff_osc_t

    !> y' = -y, but the right-hand side fails (code 42) for t > 1.
    type, extends(ode_system_t) :: failing_t
    contains
        procedure :: rhs => failing_rhs
    end type failing_t

    !> y' = -y + cos t, counting evaluations past tcrit.
    type, extends(ode_system_t) :: guard_t
        real(dp) :: tcrit = 1.0_dp
        integer :: violations = 0
    contains
        procedure :: rhs => guard_rhs
    end type guard_t

    !> Steps and scaled errors of the original LSODA (anchors, fortran_lsoda.csv) at rtol
    !! 1e-4, 1e-7, 1e-10.
    integer, parameter :: ANCHOR_ROBER(3) = [361, 1188, 2996]
    integer, parameter :: ANCHOR_VDP1000(3) = [937, 2499, 6094]
    real(dp), parameter :: ANCHOR_ERR_ROBER(3) = [3.78e-2_dp, 1.36e-1_dp, 1.65_dp]
    real(dp), parameter :: ANCHOR_ERR_VDP1000(3) = [18.1_dp, 34.3_dp, 50.5_dp]

contains

    subroutine run_radau_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call unused(exe)   ! every suite is given the executable; this one needs none
        if (t%want('radau: coefficients against the published values')) call test_coefficients(t)
        if (t%want('radau: collocation polynomial exact for a cubic')) call test_cubic(t)
        if (t%want('radau: the seven standard problems')) call test_standard(t)
        if (t%want('radau: lightly damped stiff oscillation beside a slow forced mode')) &
            call test_stiff_oscillation(t)
        if (t%want('radau: failures and input checks')) call test_failures(t)
        if (t%want('radau: integrator_t''s checks, the same for LSODA and Radau')) &
            call test_shared_checks(t)
    end subroutine run_radau_tests

    ! ---------------------------------------------------------------------------------------
    subroutine cubic_rhs(sys, t, y, ydot, stat)
        class(cubic_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(sys)
        call unused(y)
        ydot = 3.0_dp*t**2 + 2.0_dp*t
        stat%code = STATUS_OK
    end subroutine cubic_rhs

    subroutine osc_rhs(sys, t, y, ydot, stat)
        class(stiff_osc_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        ydot(1) = -sys%e*y(1) + sys%w*y(2) + sys%w*y(3)
        ydot(2) = -sys%w*y(1) - sys%e*y(2)
        ydot(3) = y(4)
        ydot(4) = -y(3) + cos(sys%nu*t)
        stat%code = STATUS_OK
    end subroutine osc_rhs

    subroutine osc_jac(sys, t, y, dfdy, stat)
        class(stiff_osc_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        call unused(t)
        call unused(y)
        dfdy = 0.0_dp
        dfdy(1, 1:3) = [-sys%e, sys%w, sys%w]
        dfdy(2, 1:2) = [-sys%w, -sys%e]
        dfdy(3, 4) = 1.0_dp
        dfdy(4, 3) = -1.0_dp
        stat%code = STATUS_OK
    end subroutine osc_jac

    logical function osc_has_jac(sys)
        class(stiff_osc_t), intent(in) :: sys
        call unused(sys)
        osc_has_jac = .true.
    end function osc_has_jac

    subroutine failing_rhs(sys, t, y, ydot, stat)
        class(failing_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(sys)
        ydot = -y
        stat%code = STATUS_OK
        if (t > 1.0_dp) call set_error(stat, 42, 'failing_t: t > 1')
    end subroutine failing_rhs

    subroutine guard_rhs(sys, t, y, ydot, stat)
        class(guard_t), intent(inout) :: sys
        real(dp), intent(in) :: t, y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        ydot = -y + cos(t)
        if (t > sys%tcrit) sys%violations = sys%violations + 1
        stat%code = STATUS_OK
    end subroutine guard_rhs

    !> Integrate sys over grid (grid(1) = t0) with a fresh Radau solver; y = y(grid(end)).
    subroutine radau_on_grid(sys, y0, grid, rtol, atol, y, st, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: y0(:), grid(:), rtol, atol(:)
        real(dp), intent(out) :: y(:)
        type(integrator_stats_t), intent(out) :: st
        type(status_t), intent(out) :: stat
        type(radau_t) :: s
        integer :: k
        y = y0
        call s%init(sys, grid(1), y0, rtol, atol, stat, max_steps=1000000)
        if (stat%code /= STATUS_OK) return
        do k = 2, size(grid)
            call s%integrate(sys, grid(k), y, stat)
            if (stat%code /= STATUS_OK) exit
        end do
        st = s%stats()
    end subroutine radau_on_grid

    ! ---------------------------------------------------------------------------------------
    !> The coefficients computed from the nodes against the closed forms of the three-stage
    !! Radau IIA method (Hairer & Wanner II, Table IV.5.6), the eigenvalues of A^-1 and the
    !! error-estimate coefficients e_i = gamma0 (-13 - 7 sqrt 6, -13 + 7 sqrt 6, -1)/3 of
    !! RADAU5; the transformation; and the quadrature order 5 of the weights b = last row.
    subroutine test_coefficients(t)
        type(tester_t), intent(inout) :: t
        type(radau_coeffs_t) :: cf
        real(dp) :: s6, a(3, 3), lam(3, 3), err
        integer :: k
        character(len=80) :: name
        cf = radau_coefficients()
        s6 = sqrt(6.0_dp)
        a(1, :) = [(88 - 7*s6)/360, (296 - 169*s6)/1800, (-2 + 3*s6)/225]
        a(2, :) = [(296 + 169*s6)/1800, (88 + 7*s6)/360, (-2 - 3*s6)/225]
        a(3, :) = [(16 - s6)/36, (16 + s6)/36, 1.0_dp/9]
        call t%check_close('A against the closed forms', maxval(abs(cf%a - a)), 0.0_dp, &
                           atol=1.0e-15_dp)
        call t%check_close('nodes c1, c2', maxval(abs(cf%c(1:2) - [(4 - s6)/10, (4 + s6)/10])), &
                           0.0_dp, atol=1.0e-16_dp)
        call t%check_close('real eigenvalue of A^-1', cf%gam, 3.637834252744496_dp, &
                           rtol=1.0e-14_dp)
        call t%check_close('complex pair of A^-1: real part', cf%alpha, 2.681082873627752_dp, &
                           rtol=1.0e-14_dp)
        call t%check_close('complex pair of A^-1: imaginary part', cf%beta, &
                           3.050430199247411_dp, rtol=1.0e-14_dp)
        call t%check_close('error coefficients e_i', maxval(abs(cf%e/cf%gam0 - &
                           [-(13 + 7*s6)/3, (-13 + 7*s6)/3, -1.0_dp/3])), 0.0_dp, &
                           atol=1.0e-13_dp)
        lam = 0.0_dp
        lam(1, 1) = cf%gam
        lam(2, 2:3) = [cf%alpha, -cf%beta]
        lam(3, 2:3) = [cf%beta, cf%alpha]
        err = maxval(abs(matmul(cf%t, matmul(lam, cf%tinv)) - cf%ainv))/maxval(abs(cf%ainv))
        call t%check_close('A^-1 = T Lambda T^-1', err, 0.0_dp, atol=1.0e-14_dp)
        call t%check_close('A A^-1 = I', maxval(abs(matmul(cf%a, cf%ainv) - &
                           reshape([1, 0, 0, 0, 1, 0, 0, 0, 1]*1.0_dp, [3, 3]))), 0.0_dp, &
                           atol=1.0e-14_dp)
        do k = 1, 5
            write (name, '(a,i0)') 'quadrature sum b_i c_i^(k-1) = 1/k, k = ', k
            call t%check_close(trim(name), sum(cf%a(3, :)*cf%c**(k - 1)), 1.0_dp/k, &
                               atol=1.0e-15_dp)
        end do
        call t%check_close('quadrature order exactly 5 (k = 6 fails)', &
                           abs(sum(cf%a(3, :)*cf%c**5) - 1.0_dp/6), 1.0e-3_dp, rtol=0.9_dp)
    end subroutine test_coefficients

    !> y' = 3 t^2 + 2 t has the cubic y = t^3 + t^2 + 1, which the collocation polynomial of
    !! degree 3 reproduces: the solution at the step ends and the dense output between them
    !! (value and derivative) are exact to roundoff at a loose tolerance.
    subroutine test_cubic(t)
        type(tester_t), intent(inout) :: t
        type(cubic_t) :: sys
        type(radau_t) :: s
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: y(1), dy(1), err, derr, tt, t0
        integer :: k, j
        call s%init(sys, 0.0_dp, [1.0_dp], 1.0e-3_dp, [1.0e-3_dp], stat)
        err = 0.0_dp
        derr = 0.0_dp
        t0 = 0.0_dp
        do k = 1, 8
            call s%step(sys, stat, 2.0_dp)
            if (stat%code /= STATUS_OK) exit
            st = s%stats()
            do j = 0, 8
                tt = t0 + (st%t_current - t0)*j/8.0_dp
                call s%dense(tt, 0, y, stat)
                err = max(err, abs(y(1) - (tt**3 + tt**2 + 1.0_dp)))
                call s%dense(tt, 1, dy, stat)
                derr = max(derr, abs(dy(1) - (3*tt**2 + 2*tt)))
            end do
            t0 = st%t_current
        end do
        call t%check('cubic: 8 steps taken', stat%code == STATUS_OK .and. st%steps == 8)
        call t%check_close('cubic: dense output exact', err, 0.0_dp, atol=1.0e-13_dp*(1 + t0**3))
        call t%check_close('cubic: dense derivative exact', derr, 0.0_dp, &
                           atol=1.0e-12_dp*(1 + t0**2))
    end subroutine test_cubic

    !> The seven problems of the anchors at rtol = 1e-4, 1e-7, 1e-10 (the anchors' atol
    !! rules, grids and references): every run finishes; the error at t_end (scaled error x
    !! rtol: the error on the scale of the solution) falls by at least 1e3 from rtol 1e-4 to
    !! 1e-10; on the stiff problems (Robertson, Van der Pol mu = 1000,
    !! HIRES, linear) the scaled error stays below 10 (the original LSODA's reaches 180);
    !! Robertson and Van der Pol mu = 1000 have smaller errors than the original LSODA at
    !! every rtol, and at 1e-4 and 1e-7 take fewer than 0.6 of its steps.
    subroutine test_standard(t)
        type(tester_t), intent(inout) :: t
        class(ode_system_t), allocatable :: sys
        real(dp), allocatable :: y0(:), grid(:), atol(:), yref(:), y(:)
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: rtol, err(3), abserr(3)
        integer :: ip, ir, steps(3)
        logical :: ok, stiff
        character(len=120) :: buf
        do ip = 1, NBENCH
            ok = .true.
            do ir = 1, 3
                rtol = 10.0_dp**(-1 - 3*ir)
                call bench_problem(BENCH_NAMES(ip), rtol, sys, y0, grid, atol, yref, stat)
                if (allocated(y)) deallocate (y)
                allocate (y(size(y0)))
                call radau_on_grid(sys, y0, grid, rtol, atol, y, st, stat)
                ok = ok .and. stat%code == STATUS_OK
                err(ir) = scaled_error(y, yref, rtol, atol)
                abserr(ir) = err(ir)*rtol       ! the error on the scale of the solution
                steps(ir) = st%steps
            end do
            write (*, '(a10,a,3i7,a,3es10.2)') trim(BENCH_NAMES(ip)), ' steps at 1e-4, 1e-7, '// &
                '1e-10:', steps, '; scaled errors', err
            call t%check(trim(BENCH_NAMES(ip))//': runs finish', ok)
            write (buf, '(a,2es10.2)') ': error falls >= 1e3 from rtol 1e-4 to 1e-10: ', &
                abserr(1), abserr(3)
            call t%check(trim(BENCH_NAMES(ip))//trim(buf), abserr(3) <= 1.0e-3_dp*abserr(1))
            stiff = any(trim(BENCH_NAMES(ip)) == ['rober  ', 'vdp1000', 'hires  ', 'linear '])
            if (stiff) call t%check(trim(BENCH_NAMES(ip))//': scaled error < 10 at every rtol', &
                                    all(err < 10.0_dp))
            if (trim(BENCH_NAMES(ip)) == 'rober') then
                call t%check('rober: smaller errors than the original LSODA', &
                             all(err < ANCHOR_ERR_ROBER))
                call t%check('rober: fewer than 0.6 of the original LSODA''s steps at 1e-4, '// &
                             '1e-7', all(steps(1:2) < 0.6_dp*ANCHOR_ROBER(1:2)))
            end if
            if (trim(BENCH_NAMES(ip)) == 'vdp1000') then
                call t%check('vdp1000: smaller errors than the original LSODA', &
                             all(err < ANCHOR_ERR_VDP1000))
                call t%check('vdp1000: fewer than 0.6 of the original LSODA''s steps at 1e-4, '// &
                             '1e-7', all(steps(1:2) < 0.6_dp*ANCHOR_VDP1000(1:2)))
            end if
        end do
    end subroutine test_standard

    !> The exact solution of stiff_osc_t: z = a cos t + b sin t + cos(nu t)/(1 - nu^2), and
    !! x = x_p + exp(A t) (x(0) - x_p(0)) with the forced response x_p = Re sum_k (i nu_k -
    !! A)^-1 w (Z_k, 0) e^(i nu_k t) to the components Z_k e^(i nu_k t) of z.
    function osc_exact(sys, tt, a, b, dx0) result(y)
        type(stiff_osc_t), intent(in) :: sys
        real(dp), intent(in) :: tt, a, b           !! time; z's free amplitudes
        real(dp), intent(in) :: dx0(2)             !! x(0) - x_p(0)
        real(dp) :: y(4)
        complex(dp) :: zk(2), m(2, 2), xp(2), det, iu
        real(dp) :: nuk(2), c, s
        integer :: k
        iu = (0.0_dp, 1.0_dp)
        nuk = [1.0_dp, sys%nu]
        zk = [cmplx(a, -b, kind=dp), cmplx(1.0_dp/(1.0_dp - sys%nu**2), 0.0_dp, kind=dp)]
        xp = (0.0_dp, 0.0_dp)
        do k = 1, 2
            ! (i nu + e) I - [[0, w], [-w, 0]]: inverse of [[p, -w], [w, p]], p = i nu + e
            det = (iu*nuk(k) + sys%e)**2 + sys%w**2
            m(1, :) = [iu*nuk(k) + sys%e, cmplx(sys%w, 0.0_dp, kind=dp)]
            m(2, :) = [cmplx(-sys%w, 0.0_dp, kind=dp), iu*nuk(k) + sys%e]
            xp = xp + matmul(m/det, [sys%w*zk(k), (0.0_dp, 0.0_dp)])*exp(iu*nuk(k)*tt)
        end do
        c = exp(-sys%e*tt)*cos(sys%w*tt)
        s = exp(-sys%e*tt)*sin(sys%w*tt)
        y(1:2) = real(xp) + [c*dx0(1) + s*dx0(2), -s*dx0(1) + c*dx0(2)]
        y(3) = a*cos(tt) + b*sin(tt) + cos(sys%nu*tt)/(1.0_dp - sys%nu**2)
        y(4) = -a*sin(tt) + b*cos(tt) - sys%nu*sin(sys%nu*tt)/(1.0_dp - sys%nu**2)
    end function osc_exact

    !> Eigenvalues -e +- i w with w/e = 1000 (e = 10, w = 1e4) beside the slow oscillator z
    !! forced at nu = 0.5, which drives the stiff pair; tau = 0 ... 10 (1.6 periods of z).
    !! Started on its forced response, the stiff pair stays there: at rtol 1e-6, 1e-8, 1e-10
    !! the error of every component is within 10 rtol at 100 output times, and the mean
    !! step is over 100/w (Radau steps over the oscillation it need not resolve; an explicit
    !! method would need steps below 3/w).  (A start off the forced response rings with
    !! amplitude 1 for a time ln(1/rtol)/e; that ringing is part of the solution, and every
    !! error-controlled method resolves it while it lasts.)
    subroutine test_stiff_oscillation(t)
        type(tester_t), intent(inout) :: t
        type(stiff_osc_t) :: sys
        type(radau_t) :: s
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp), parameter :: a = 0.3_dp, b = -0.2_dp, tend = 10.0_dp
        real(dp) :: y(4), ye(4), y0(4), rtol, errs, errx, dx0(2), hmean
        integer :: ir, k, icase
        character(len=120) :: buf
        do icase = 1, 1
            dx0 = 0.0_dp
            y0 = osc_exact(sys, 0.0_dp, a, b, [0.0_dp, 0.0_dp])
            y0(1:2) = y0(1:2) + dx0
            do ir = 1, 3
                rtol = 10.0_dp**(-4 - 2*ir)
                call s%init(sys, 0.0_dp, y0, rtol, [rtol], stat)
                errs = 0.0_dp
                errx = 0.0_dp
                do k = 1, 100
                    if (stat%code == STATUS_OK) call s%integrate(sys, k*tend/100, y, stat)
                    ye = osc_exact(sys, k*tend/100, a, b, dx0)
                    errs = max(errs, maxval(abs(y(3:4) - ye(3:4))))
                    errx = max(errx, maxval(abs(y(1:2) - ye(1:2))))
                end do
                st = s%stats()
                hmean = tend/max(1, st%steps)
                write (buf, '(a,es8.1,a)') 'stiff oscillation, rtol ', rtol, ': '
                write (*, '(a,i6,a,f8.1,a,2es10.2)') '  '//trim(buf)//' steps', st%steps, &
                    ', mean step w h', hmean*sys%w, ', errors slow, stiff', errs, errx
                call t%check(trim(buf)//'finishes', stat%code == STATUS_OK)
                call t%check(trim(buf)//'slow mode within 10 rtol', errs <= 10*rtol)
                call t%check(trim(buf)//'stiff pair within 10 rtol', errx <= 10*rtol)
                call t%check(trim(buf)//'mean step > 100/w', hmean > 100.0_dp/sys%w)
            end do
        end do
    end subroutine test_stiff_oscillation

    !> Bad arguments, a failing right-hand side, max_steps, dense output outside the step,
    !! tcrit never passed (not even by an evaluation).
    subroutine test_failures(t)
        type(tester_t), intent(inout) :: t
        type(radau_t) :: s
        type(failing_t) :: fsys
        type(guard_t) :: g
        type(cubic_t) :: c
        type(status_t) :: stat
        type(integrator_stats_t) :: st
        real(dp) :: y(1), y2(2)
        call s%init(fsys, 0.0_dp, [1.0_dp], 0.0_dp, [1.0e-8_dp], stat)
        call t%check('rtol = 0 refused', stat%code == RADAU_ERR_ILLEGAL_INPUT)
        call s%init(fsys, 0.0_dp, [1.0_dp], 1.0e-15_dp, [1.0e-8_dp], stat)
        call t%check('rtol = 1e-15: too much accuracy', stat%code == RADAU_ERR_TOO_MUCH_ACCURACY)
        call s%init(fsys, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp, 1.0e-8_dp], stat)
        call t%check('atol of the wrong size refused', stat%code == RADAU_ERR_ILLEGAL_INPUT)
        call s%init(fsys, 0.0_dp, [1.0_dp], 1.0e-6_dp, [-1.0_dp], stat)
        call t%check('negative atol refused', stat%code == RADAU_ERR_ILLEGAL_INPUT)
        call s%init(fsys, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call s%integrate(fsys, 2.0_dp, y, stat)
        st = s%stats()
        call t%check('the right-hand side''s failure comes back with its code', stat%code == 42)
        call t%check('... and the time reached (<= 1)', st%t_current <= 1.0_dp .and. &
                     index(stat%msg, 'radau at t =') > 0)
        call t%check_close('... and the solution up to it', y(1), exp(-st%t_current), &
                           rtol=1.0e-5_dp)
        call s%init(c, 0.0_dp, [1.0_dp], 1.0e-10_dp, [1.0e-12_dp], stat, max_steps=3, &
                    hmax=0.01_dp)
        call s%integrate(c, 1.0_dp, y, stat)
        call t%check('max_steps stops integrate', stat%code == RADAU_ERR_MAX_STEPS)
        call s%dense(100.0_dp, 0, y, stat)
        call t%check('dense outside the last step refused', stat%code == RADAU_ERR_ILLEGAL_INPUT)
        call s%dense(0.0_dp, 0, y2, stat)
        call t%check('dense with the wrong size refused', stat%code == RADAU_ERR_ILLEGAL_INPUT)
        call s%init(g, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-10_dp], stat, tcrit=1.0_dp)
        call s%integrate(g, 1.0_dp, y, stat)
        st = s%stats()
        call t%check('tcrit: reached exactly', stat%code == STATUS_OK .and. &
                     st%t_current == 1.0_dp)
        call t%check('tcrit: no evaluation beyond it', g%violations == 0)
        call s%step(g, stat)
        call t%check('tcrit: a step from it refused', stat%code == RADAU_ERR_ILLEGAL_INPUT)
        call t%check_close('tcrit: y(1) of y'' = -y + cos t', y(1), &
                           0.5_dp*(cos(1.0_dp) + sin(1.0_dp)) + 0.5_dp*exp(-1.0_dp), &
                           rtol=1.0e-7_dp)
    end subroutine test_failures

    !> The checks integrator_t makes for every integrator, through class(integrator_t) as a
    !! driver holds it: each refusal with the integrator's own code and a message that
    !! starts with its name, the same for LSODA and Radau.
    subroutine test_shared_checks(t)
        type(tester_t), intent(inout) :: t
        class(integrator_t), allocatable :: s
        type(guard_t) :: g
        type(status_t) :: stat
        type(integrator_stats_t) :: st
        real(dp) :: y(1), y2(2), ds(1, 1), inf
        integer :: m, bad, too_many
        character(len=5) :: nm
        inf = ieee_value(1.0_dp, ieee_positive_inf)
        do m = 1, 2
            if (m == 1) then
                call new_integrator(SOLVER_LSODA, s)
                nm = 'lsoda'
                bad = LSODA_ERR_ILLEGAL_INPUT
                too_many = LSODA_ERR_MAX_STEPS
            else
                call new_integrator(SOLVER_RADAU, s)
                nm = 'radau'
                bad = RADAU_ERR_ILLEGAL_INPUT
                too_many = RADAU_ERR_MAX_STEPS
            end if
            call t%check(nm//': name', s%name() == nm)
            y = 7.0_dp
            call s%integrate(g, 1.0_dp, y, stat)
            call t%check(nm//': integrate before init refused, y = 0', stat%code == bad .and. &
                         y(1) == 0.0_dp .and. index(stat%msg, nm//' integrate') == 1)
            call s%step(g, stat)
            call t%check(nm//': step before init refused', stat%code == bad)
            call s%init(g, 0.0_dp, [real(dp) ::], 1.0e-6_dp, [1.0e-8_dp], stat)
            call t%check(nm//': an empty state refused', stat%code == bad .and. &
                         index(stat%msg, nm//' init') == 1)
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp, 1.0e-8_dp], stat)
            call t%check(nm//': atol of the wrong size refused', stat%code == bad)
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-6_dp, [-1.0e-8_dp], stat)
            call t%check(nm//': a negative atol refused', stat%code == bad)
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-6_dp, [inf], stat)
            call t%check(nm//': an infinite atol refused', stat%code == bad)
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat, hmax=0.0_dp)
            call t%check(nm//': hmax = 0 refused', stat%code == bad)
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat, max_steps=0)
            call t%check(nm//': max_steps = 0 refused', stat%code == bad)
            ! a good start, then calls out of order or of the wrong shape
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-10_dp], stat)
            call t%check(nm//': init', stat%code == STATUS_OK)
            call s%dense(0.0_dp, 0, y2, stat)
            call t%check(nm//': dense with the wrong size refused', stat%code == bad)
            call s%sens_dense(0.0_dp, 0, ds, stat)
            call t%check(nm//': sens_dense without sensitivities refused', stat%code == bad)
            call s%integrate(g, 1.0_dp, y, stat)
            call t%check_close(nm//': y(1) of y'' = -y + cos t', y(1), &
                               0.5_dp*(cos(1.0_dp) + sin(1.0_dp)) + 0.5_dp*exp(-1.0_dp), &
                               rtol=1.0e-6_dp)
            call s%sens_init(g, reshape([1.0_dp], [1, 1]), stat)
            call t%check(nm//': sens_init after the start refused', stat%code == bad .and. &
                         index(stat%msg, nm//' sens_init') == 1)
            call s%integrate(g, 0.5_dp, y, stat)
            call t%check(nm//': tout behind the last output refused', stat%code == bad)
            st = s%stats()
            call s%dense(st%t_current + 10.0_dp*abs(st%h_last), 0, y, stat)
            call t%check(nm//': dense outside the last step refused', stat%code == bad)
            call s%set_tcrit(0.5_dp, stat)
            call t%check(nm//': tcrit behind the time reached refused', stat%code == bad)
            call s%integrate(g, 2.0_dp, y, stat)
            call t%check(nm//': ... and the old setting (none) kept', stat%code == STATUS_OK)
            ! max_steps, and a step from tcrit
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-10_dp], stat, max_steps=3, &
                        hmax=0.01_dp)
            call s%integrate(g, 1.0_dp, y, stat)
            st = s%stats()
            call t%check(nm//': max_steps stops integrate after max_steps steps', &
                         stat%code == too_many .and. st%steps == 3 .and. &
                         index(stat%msg, nm//':') == 1)
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-10_dp], stat, tcrit=0.0_dp)
            call s%step(g, stat)
            call t%check(nm//': a first step from tcrit refused', stat%code == bad)
            call s%init(g, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-10_dp], stat, tcrit=0.25_dp)
            call s%integrate(g, 0.25_dp, y, stat)
            st = s%stats()
            call t%check(nm//': integrate to tcrit reaches it', stat%code == STATUS_OK .and. &
                         st%t_current == 0.25_dp)
            call s%step(g, stat)
            call t%check(nm//': a step from tcrit refused', stat%code == bad)
            deallocate (s)
        end do
    end subroutine test_shared_checks

end module test_radau
