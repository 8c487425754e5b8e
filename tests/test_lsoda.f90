!> Tests of module lsoda and the benchmark problems they share with bench_integrator.
!!
!! Problems (definitions, tolerance rules, output grids and reference values exactly as in
!! the anchors, shared/reference/integrator/anchors.md):
!! rober (Robertson), vdp (Van der Pol, parameter mu), arenstorf, hires, pendulum
!! (theta'' = -sin theta), linear (3x3 stiff, eigenvalues -1, -1e3, -1e6), plus a harmonic
!! oscillator and exponential decay with exact solutions; lapack_wrap's small inverse, which
!! the sensitivities' corrector uses.  None counts anything: the
!! solver's stats() do.
module test_lsoda
    use kinds, only: dp, pi
    use status, only: status_t, set_error, STATUS_OK
    use ode_system, only: ode_system_t, integrator_stats_t
    use lsoda, only: lsoda_t, METHOD_ADAMS, METHOD_BDF
    use status, only: LSODA_ERR_MAX_STEPS, LSODA_ERR_TOO_MUCH_ACCURACY, LSODA_ERR_ERROR_TEST, &
        LSODA_ERR_CONVERGENCE, LSODA_ERR_ILLEGAL_INPUT, LSODA_ERR_SINGULAR
    use testing, only: tester_t
    use lapack_wrap, only: la_small_inverse, la_lu_factor, la_lu_solve_many
    use unused_arg, only: unused
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    implicit none
    private

    public :: run_lsoda_tests, bench_problem, scaled_error, solve_on_grid

    !> Number of benchmark problems and their names (bench_problem keys).
    integer, parameter, public :: NBENCH = 7
    character(len=9), parameter, public :: BENCH_NAMES(NBENCH) = [character(len=9) :: &
        'rober', 'vdp1000', 'vdp1', 'arenstorf', 'hires', 'pendulum', 'linear']

    !> Robertson chemical kinetics, k1=0.04, k2=3e7, k3=1e4.
    type, extends(ode_system_t), public :: rober_t
        logical :: use_jac = .false.    !! give the analytic Jacobian
    contains
        procedure :: rhs => rober_rhs
        procedure :: jacobian => rober_jac
        procedure :: has_jacobian => rober_has_jac
    end type rober_t

    !> Van der Pol: y1' = y2, y2' = mu (1 - y1^2) y2 - y1.
    type, extends(ode_system_t), public :: vdp_t
        real(dp) :: mu = 1000.0_dp
    contains
        procedure :: rhs => vdp_rhs
    end type vdp_t

    !> Arenstorf orbit (restricted three-body problem), y = (x, y, x', y').
    type, extends(ode_system_t), public :: arenstorf_t
    contains
        procedure :: rhs => arenstorf_rhs
    end type arenstorf_t

    !> HIRES, 8 equations (Bari IVP test set).
    type, extends(ode_system_t), public :: hires_t
    contains
        procedure :: rhs => hires_rhs
    end type hires_t

    !> Simple pendulum theta'' = -sin(theta), y = (theta, theta').
    type, extends(ode_system_t), public :: pendulum_t
    contains
        procedure :: rhs => pendulum_rhs
    end type pendulum_t

    !> y' = A y, A = V diag(-1, -1e3, -1e6) V^-1, V = [[1,1,1],[1,-1,1],[1,1,-1]].
    type, extends(ode_system_t), public :: linear_t
        logical :: use_jac = .false.    !! give the analytic Jacobian (A)
    contains
        procedure :: rhs => linear_rhs
        procedure :: jacobian => linear_jac
        procedure :: has_jacobian => linear_has_jac
    end type linear_t

    !> Harmonic oscillator y1' = omega y2, y2' = -omega y1.
    type, extends(ode_system_t), public :: harmonic_t
        real(dp) :: omega = 1.0_dp
    contains
        procedure :: rhs => harmonic_rhs
    end type harmonic_t

    !> Exponential decay y' = -k y (every component).
    type, extends(ode_system_t), public :: decay_t
        real(dp) :: k = 1.0_dp
    contains
        procedure :: rhs => decay_rhs
    end type decay_t

    ! ---- test-only systems
    !> y' = -y until t_bad, then a jump of f to a huge value (error-test failures).
    type, extends(ode_system_t) :: jump_t
        real(dp) :: t_bad = 1.0_dp
    contains
        procedure :: rhs => jump_rhs
    end type jump_t

    !> y' = -y until t_bad, then f oscillating violently in y (corrector cannot converge).
    type, extends(ode_system_t) :: wild_t
        real(dp) :: t_bad = 1.0_dp
    contains
        procedure :: rhs => wild_rhs
    end type wild_t

    !> Stiff y' = -1e4 (y - cos t); its Jacobian turns exactly singular (P = -c [[1,1],[1,1]])
    !! after t_bad.
    type, extends(ode_system_t) :: singular_t
        real(dp) :: t_bad = 1.0_dp
    contains
        procedure :: rhs => singular_rhs
        procedure :: jacobian => singular_jac
        procedure :: has_jacobian => singular_has_jac
    end type singular_t

    !> y' = -y, but the rhs reports an error (code 42) for t > t_bad.
    type, extends(ode_system_t) :: failing_t
        real(dp) :: t_bad = 1.0_dp
    contains
        procedure :: rhs => failing_rhs
    end type failing_t

    !> y' = -y + cos(t) checking that it is never evaluated past tcrit.
    type, extends(ode_system_t) :: guard_t
        real(dp) :: tcrit = 1.0_dp
        integer :: violations = 0
    contains
        procedure :: rhs => guard_rhs
    end type guard_t

    real(dp), parameter :: RK1 = 0.04_dp, RK2 = 3.0e7_dp, RK3 = 1.0e4_dp
    real(dp), parameter :: AM = 0.012277471_dp, AMP = 1.0_dp - AM
    real(dp), parameter :: AREN_T = 17.0652165601579625588917206249_dp
    real(dp), parameter :: AREN_Y0(4) = [0.994_dp, 0.0_dp, 0.0_dp, &
        -2.00158510637908252240537862224_dp]
    real(dp), parameter :: HIRES_TEND = 321.8122_dp
    real(dp), parameter :: LIN_A(3, 3) = reshape([-500500.0_dp, -499500.0_dp, 499500.0_dp, &
        499.5_dp, -500.5_dp, 499.5_dp, 499999.5_dp, 499999.5_dp, -500000.5_dp], [3, 3])
    real(dp), parameter :: LIN_V(3, 3) = reshape([1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, &
        1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp], [3, 3])
    real(dp), parameter :: LIN_LAM(3) = [-1.0_dp, -1.0e3_dp, -1.0e6_dp]

    ! reference values y(t_end) of the anchors
    real(dp), parameter :: REF_ROBER(3) = [5.2083451767988070e-08_dp, &
        2.0833381779253091e-13_dp, 9.9999994791634328e-01_dp]
    real(dp), parameter :: REF_VDP1000(2) = [-1.5106069367439949e+00_dp, &
        1.1783800007311442e-03_dp]
    real(dp), parameter :: REF_VDP1(2) = [2.0081497621749396e+00_dp, &
        -4.2508875273232730e-02_dp]
    real(dp), parameter :: REF_HIRES(8) = [7.3713125733256685e-04_dp, &
        1.4424857263161851e-04_dp, 5.8887297409675752e-05_dp, 1.1756513432831491e-03_dp, &
        2.3863561988313308e-03_dp, 6.2389682527427964e-03_dp, 2.8499983951857689e-03_dp, &
        2.8500016048142308e-03_dp]
    real(dp), parameter :: REF_PEND(2) = [1.9823256531570315e+00_dp, 1.7964074259093457e-01_dp]
    real(dp), parameter :: REF_LINEAR(3) = [4.5399929762484854e-05_dp, &
        4.5399929762484854e-05_dp, 4.5399929762484854e-05_dp]

contains

    ! ====================================================================================
    ! Right-hand sides
    ! ====================================================================================

    subroutine rober_rhs(sys, t, y, ydot, stat)
        class(rober_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: a, b, c
        call unused(sys)
        call unused(t)
        a = RK1*y(1)
        b = RK3*y(2)*y(3)
        c = RK2*y(2)*y(2)
        ydot(1) = -a + b
        ydot(2) = a - b - c
        ydot(3) = c
        stat%code = STATUS_OK
    end subroutine rober_rhs

    subroutine rober_jac(sys, t, y, dfdy, stat)
        class(rober_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        call unused(sys)
        call unused(t)
        dfdy(1, :) = [-RK1, RK3*y(3), RK3*y(2)]
        dfdy(2, :) = [RK1, -RK3*y(3) - 2.0_dp*RK2*y(2), -RK3*y(2)]
        dfdy(3, :) = [0.0_dp, 2.0_dp*RK2*y(2), 0.0_dp]
        stat%code = STATUS_OK
    end subroutine rober_jac

    logical function rober_has_jac(sys)
        class(rober_t), intent(in) :: sys
        rober_has_jac = sys%use_jac
    end function rober_has_jac

    subroutine vdp_rhs(sys, t, y, ydot, stat)
        class(vdp_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(t)
        ydot(1) = y(2)
        ydot(2) = sys%mu*(1.0_dp - y(1)*y(1))*y(2) - y(1)
        stat%code = STATUS_OK
    end subroutine vdp_rhs

    subroutine arenstorf_rhs(sys, t, y, ydot, stat)
        class(arenstorf_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: d1, d2
        call unused(sys)
        call unused(t)
        d1 = ((y(1) + AM)**2 + y(2)**2)**1.5_dp
        d2 = ((y(1) - AMP)**2 + y(2)**2)**1.5_dp
        ydot(1) = y(3)
        ydot(2) = y(4)
        ydot(3) = y(1) + 2.0_dp*y(4) - AMP*(y(1) + AM)/d1 - AM*(y(1) - AMP)/d2
        ydot(4) = y(2) - 2.0_dp*y(3) - AMP*y(2)/d1 - AM*y(2)/d2
        stat%code = STATUS_OK
    end subroutine arenstorf_rhs

    subroutine hires_rhs(sys, t, y, ydot, stat)
        class(hires_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: p
        call unused(sys)
        call unused(t)
        p = 280.0_dp*y(6)*y(8)
        ydot(1) = -1.71_dp*y(1) + 0.43_dp*y(2) + 8.32_dp*y(3) + 0.0007_dp
        ydot(2) = 1.71_dp*y(1) - 8.75_dp*y(2)
        ydot(3) = -10.03_dp*y(3) + 0.43_dp*y(4) + 0.035_dp*y(5)
        ydot(4) = 8.32_dp*y(2) + 1.71_dp*y(3) - 1.12_dp*y(4)
        ydot(5) = -1.745_dp*y(5) + 0.43_dp*y(6) + 0.43_dp*y(7)
        ydot(6) = -p + 0.69_dp*y(4) + 1.71_dp*y(5) - 0.43_dp*y(6) + 0.69_dp*y(7)
        ydot(7) = p - 1.81_dp*y(7)
        ydot(8) = -p + 1.81_dp*y(7)
        stat%code = STATUS_OK
    end subroutine hires_rhs

    subroutine pendulum_rhs(sys, t, y, ydot, stat)
        class(pendulum_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(sys)
        call unused(t)
        ydot(1) = y(2)
        ydot(2) = -sin(y(1))
        stat%code = STATUS_OK
    end subroutine pendulum_rhs

    subroutine linear_rhs(sys, t, y, ydot, stat)
        class(linear_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(sys)
        call unused(t)
        ydot(1) = LIN_A(1, 1)*y(1) + LIN_A(1, 2)*y(2) + LIN_A(1, 3)*y(3)
        ydot(2) = LIN_A(2, 1)*y(1) + LIN_A(2, 2)*y(2) + LIN_A(2, 3)*y(3)
        ydot(3) = LIN_A(3, 1)*y(1) + LIN_A(3, 2)*y(2) + LIN_A(3, 3)*y(3)
        stat%code = STATUS_OK
    end subroutine linear_rhs

    subroutine linear_jac(sys, t, y, dfdy, stat)
        class(linear_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        call unused(sys)
        call unused(t)
        call unused(y)
        dfdy = LIN_A
        stat%code = STATUS_OK
    end subroutine linear_jac

    logical function linear_has_jac(sys)
        class(linear_t), intent(in) :: sys
        linear_has_jac = sys%use_jac
    end function linear_has_jac

    subroutine harmonic_rhs(sys, t, y, ydot, stat)
        class(harmonic_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(t)
        ydot(1) = sys%omega*y(2)
        ydot(2) = -sys%omega*y(1)
        stat%code = STATUS_OK
    end subroutine harmonic_rhs

    subroutine decay_rhs(sys, t, y, ydot, stat)
        class(decay_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(t)
        ydot = -sys%k*y
        stat%code = STATUS_OK
    end subroutine decay_rhs

    subroutine jump_rhs(sys, t, y, ydot, stat)
        class(jump_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        if (t <= sys%t_bad) then
            ydot = -y
        else
            ydot = 1.0e100_dp
        end if
        stat%code = STATUS_OK
    end subroutine jump_rhs

    subroutine wild_rhs(sys, t, y, ydot, stat)
        class(wild_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        if (t <= sys%t_bad) then
            ydot = -y
        else
            ydot = 1.0e8_dp*sin(1.0e9_dp*y)
        end if
        stat%code = STATUS_OK
    end subroutine wild_rhs

    subroutine singular_rhs(sys, t, y, ydot, stat)
        class(singular_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        call unused(sys)
        ydot = -1.0e4_dp*(y - cos(t))
        stat%code = STATUS_OK
    end subroutine singular_rhs

    subroutine singular_jac(sys, t, y, dfdy, stat)
        class(singular_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        call unused(y)
        if (t <= sys%t_bad) then
            dfdy = 0.0_dp
            dfdy(1, 1) = -1.0e4_dp
            dfdy(2, 2) = -1.0e4_dp
        else
            ! h*l0*J dwarfs I: P = I - h*l0*J rounds to -c*[[1,1],[1,1]], exactly singular
            dfdy = 1.0e200_dp
        end if
        stat%code = STATUS_OK
    end subroutine singular_jac

    logical function singular_has_jac(sys)
        class(singular_t), intent(in) :: sys
        call unused(sys)
        singular_has_jac = .true.
    end function singular_has_jac

    subroutine failing_rhs(sys, t, y, ydot, stat)
        class(failing_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        ydot = -y
        stat%code = STATUS_OK
        if (t > sys%t_bad) call set_error(stat, 42, 'model left its domain')
    end subroutine failing_rhs

    subroutine guard_rhs(sys, t, y, ydot, stat)
        class(guard_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        if (t > sys%tcrit) sys%violations = sys%violations + 1
        ydot = -y + cos(t)
        stat%code = STATUS_OK
    end subroutine guard_rhs

    ! ====================================================================================
    ! Benchmark problems (shared with bench_integrator)
    ! ====================================================================================

    !> Problem `name` of the anchors at tolerance rtol: system, initial state, output grid
    !! (grid(1) = t0), absolute tolerances by the anchors' rule, and reference y(t_end).
    !! stat: STATUS_OK or 1 for an unknown name.
    subroutine bench_problem(name, rtol, sys, y0, grid, atol, yref, stat)
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: rtol
        class(ode_system_t), allocatable, intent(out) :: sys
        real(dp), allocatable, intent(out) :: y0(:), grid(:), atol(:), yref(:)
        type(status_t), intent(out) :: stat
        integer :: k
        select case (trim(name))
        case ('rober')
            allocate (rober_t :: sys)
            y0 = [1.0_dp, 0.0_dp, 0.0_dp]
            allocate (grid(13))
            grid(1) = 0.0_dp
            do k = 0, 11
                grid(k + 2) = 0.4_dp*10.0_dp**k
            end do
            atol = rtol*[1.0e-2_dp, 1.0e-6_dp, 1.0e-2_dp]
            yref = REF_ROBER
        case ('vdp1000')
            allocate (vdp_t :: sys)
            select type (sys)
            type is (vdp_t)
                sys%mu = 1000.0_dp
            end select
            y0 = [2.0_dp, 0.0_dp]
            grid = linspace(0.0_dp, 3000.0_dp, 100)
            atol = [1.0e-3_dp, 1.0e-3_dp]*rtol
            yref = REF_VDP1000
        case ('vdp1')
            allocate (vdp_t :: sys)
            select type (sys)
            type is (vdp_t)
                sys%mu = 1.0_dp
            end select
            y0 = [2.0_dp, 0.0_dp]
            grid = linspace(0.0_dp, 20.0_dp, 100)
            atol = [rtol, rtol]
            yref = REF_VDP1
        case ('arenstorf')
            allocate (arenstorf_t :: sys)
            y0 = AREN_Y0
            grid = linspace(0.0_dp, AREN_T, 100)
            atol = [rtol, rtol, rtol, rtol]
            yref = AREN_Y0
        case ('hires')
            allocate (hires_t :: sys)
            y0 = [1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0057_dp]
            grid = linspace(0.0_dp, HIRES_TEND, 100)
            allocate (atol(8))
            atol = 1.0e-4_dp*rtol
            yref = REF_HIRES
        case ('pendulum')
            allocate (pendulum_t :: sys)
            y0 = [2.0_dp, 0.0_dp]
            grid = linspace(0.0_dp, 100.0_dp, 100)
            atol = [rtol, rtol]
            yref = REF_PEND
        case ('linear')
            allocate (linear_t :: sys)
            y0 = [3.0_dp, 1.0_dp, 1.0_dp]
            grid = linspace(0.0_dp, 10.0_dp, 100)
            allocate (atol(3))
            atol = 1.0e-6_dp*rtol
            yref = REF_LINEAR
        case default
            allocate (decay_t :: sys)
            y0 = [1.0_dp]
            grid = [0.0_dp, 1.0_dp]
            atol = [rtol]
            yref = [exp(-1.0_dp)]
            call set_error(stat, 1, 'bench_problem: unknown problem '//trim(name))
            return
        end select
        stat%code = STATUS_OK
    end subroutine bench_problem

    !> n+1 equally spaced points from a to b.
    pure function linspace(a, b, n) result(x)
        real(dp), intent(in) :: a, b
        integer, intent(in) :: n
        real(dp) :: x(n + 1)
        integer :: i
        do i = 0, n
            x(i + 1) = a + (b - a)*real(i, dp)/real(n, dp)
        end do
        x(n + 1) = b
    end function linspace

    !> max_i |y_i - ref_i| / (atol_i + rtol |ref_i|).
    pure real(dp) function scaled_error(y, yref, rtol, atol)
        real(dp), intent(in) :: y(:), yref(:)
        real(dp), intent(in) :: rtol
        real(dp), intent(in) :: atol(:)
        integer :: i
        real(dp) :: at
        scaled_error = 0.0_dp
        do i = 1, size(y)
            at = atol(min(i, size(atol)))
            scaled_error = max(scaled_error, abs(y(i) - yref(i))/(at + rtol*abs(yref(i))))
        end do
    end function scaled_error

    !> Integrate sys over grid (grid(1) = t0) with a fresh solver; y = y(grid(end)).
    subroutine solve_on_grid(sys, y0, grid, rtol, atol, y, st, stat)
        class(ode_system_t), intent(inout) :: sys
        real(dp), intent(in) :: y0(:), grid(:)
        real(dp), intent(in) :: rtol
        real(dp), intent(in) :: atol(:)
        real(dp), intent(out) :: y(:)
        type(integrator_stats_t), intent(out) :: st
        type(status_t), intent(out) :: stat
        type(lsoda_t) :: s
        integer :: k
        y = y0
        call s%init(sys, grid(1), y0, rtol, atol, stat, max_steps=1000000)
        if (stat%code /= STATUS_OK) return
        do k = 2, size(grid)
            call s%integrate(sys, grid(k), y, stat)
            if (stat%code /= STATUS_OK) exit
        end do
        st = s%stats()
    end subroutine solve_on_grid

    ! ====================================================================================
    ! Tests
    ! ====================================================================================

    !> All lsoda test suites (each selectable by name through t%want).
    subroutine run_lsoda_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call unused(exe)   ! every suite is given the executable; this one needs none
        if (t%want('lsoda_exact')) call test_exact(t)
        if (t%want('lsoda_problems')) call test_problems(t)
        if (t%want('lsoda_tolerance')) call test_tolerance(t)
        if (t%want('lsoda_failures')) call test_failures(t)
        if (t%want('lsoda_interleave')) call test_interleave(t)
        if (t%want('lsoda_dense_tcrit')) call test_dense_tcrit(t)
        if (t%want('lsoda_method_options')) call test_method_options(t)
        if (t%want('lsoda_small_inverse')) call test_small_inverse(t)
    end subroutine run_lsoda_tests

    !> lapack_wrap's written-out la_small_inverse (the sensitivities' matrix of an Adams
    !! step): A A^-1 = I to 1e-13 for I - h J of orders 1, 2, 5 and 10 with entries of all
    !! signs, for a matrix whose first pivot is 0 (an interchange of every row), and equal
    !! to LAPACK's LU solves of the identity to 1e-13; an exactly singular matrix refused
    !! (ERR_NUMERIC naming the column).
    subroutine test_small_inverse(t)
        type(tester_t), intent(inout) :: t
        integer, parameter :: orders(4) = [1, 2, 5, 10]
        real(dp), allocatable :: a(:, :), ai(:, :), lu(:, :), x(:, :), eye(:, :)
        integer, allocatable :: ipiv(:)
        type(status_t) :: st, st2
        integer :: k, n, i, j, kind
        character(len=40) :: label
        do kind = 1, 2
            do k = 1, size(orders)
                n = orders(k)
                allocate (a(n, n), ai(n, n), lu(n, n), x(n, n), eye(n, n), ipiv(n))
                eye = 0.0_dp
                do i = 1, n
                    eye(i, i) = 1.0_dp
                end do
                do j = 1, n
                    do i = 1, n
                        a(i, j) = 0.3_dp*sin(1.7_dp*i + 0.9_dp*j*j)
                    end do
                end do
                if (kind == 1) then
                    a = eye - a
                else
                    ! the first pivot 0, the rows in another order
                    a(1, 1) = 0.0_dp
                    a = a(n:1:-1, :) + 0.5_dp*eye
                end if
                write (label, '(a,i0,a)') 'small inverse, order ', n, &
                    trim(merge('             ', ', rows turned', kind == 1))
                call la_small_inverse(n, a, ai, st)
                call t%check(trim(label)//': computed', st%code == STATUS_OK)
                call t%check_close(trim(label)//': A A^-1 = I', &
                                   1.0_dp + maxval(abs(matmul(a, ai) - eye)), 1.0_dp, 1.0e-13_dp)
                lu = a
                call la_lu_factor(lu, ipiv, st2)
                x = eye
                if (st2%code == STATUS_OK) call la_lu_solve_many(lu, ipiv, x, st2)
                call t%check_close(trim(label)//': = LAPACK''s LU solves', &
                                   1.0_dp + maxval(abs(ai - x))/maxval(abs(x)), 1.0_dp, 1.0e-13_dp)
                deallocate (a, ai, lu, x, eye, ipiv)
            end do
        end do
        allocate (a(3, 3), ai(3, 3))
        a = reshape([1.0_dp, 2.0_dp, 3.0_dp, 2.0_dp, 4.0_dp, 6.0_dp, 0.0_dp, 1.0_dp, 1.0_dp], &
                    [3, 3])
        call la_small_inverse(3, a, ai, st)
        call t%check('small inverse: a singular matrix is refused, naming the column', &
                     st%code /= STATUS_OK .and. index(st%msg, 'column 2') > 0)
    end subroutine test_small_inverse

    !> start_bdf and nonstiff_only on the stiff linear problem (eigenvalues -1, -1e3, -1e6)
    !! over t = 0 ... 0.01: with start_bdf the first step is BDF; with nonstiff_only the
    !! method stays Adams throughout and, limited by stability, takes far more steps than
    !! the automatic switching; all three agree on the solution; the two options together
    !! are refused.
    subroutine test_method_options(t)
        type(tester_t), intent(inout) :: t
        type(linear_t) :: lin
        type(lsoda_t) :: s
        type(status_t) :: st
        type(integrator_stats_t) :: sa, sb, sn
        real(dp) :: y0(3), ya(3), yb(3), yn(3)
        real(dp), parameter :: rtol = 1.0e-6_dp, atol = 1.0e-10_dp, tend = 0.01_dp
        y0 = [1.0_dp, 2.0_dp, 3.0_dp]
        call s%init(lin, 0.0_dp, y0, rtol, [atol], st)
        call s%integrate(lin, tend, ya, st)
        sa = s%stats()
        call t%check('options: automatic run succeeds and ends in BDF', st%code == STATUS_OK &
            .and. sa%method_last == METHOD_BDF)
        call s%set_options(start_bdf=.true.)
        call s%init(lin, 0.0_dp, y0, rtol, [atol], st)
        call s%set_options()
        call s%step(lin, st, tend)
        sb = s%stats()
        call t%check('start_bdf: the first step is BDF', st%code == STATUS_OK .and. &
            sb%method_last == METHOD_BDF .and. sb%steps == 1)
        call s%integrate(lin, tend, yb, st)
        sb = s%stats()
        call s%set_options(nonstiff_only=.true.)
        call s%init(lin, 0.0_dp, y0, rtol, [atol], st)
        call s%set_options()
        call s%integrate(lin, tend, yn, st)
        sn = s%stats()
        write (*, '(a,3i8)') '  steps: automatic, start_bdf, nonstiff_only', sa%steps, &
            sb%steps, sn%steps
        call t%check('nonstiff_only: stays Adams, never switches', st%code == STATUS_OK .and. &
            sn%method_last == METHOD_ADAMS .and. sn%method_switches == 0)
        call t%check('nonstiff_only: > 10 times the steps of the automatic run', &
            sn%steps > 10*sa%steps)
        call t%check('options: the three runs agree (1e-4 relative)', &
            all(abs(yb - ya) <= 1.0e-4_dp*abs(ya) + 1.0e-8_dp) .and. &
            all(abs(yn - ya) <= 1.0e-4_dp*abs(ya) + 1.0e-8_dp))
        call s%set_options(start_bdf=.true., nonstiff_only=.true.)
        call s%init(lin, 0.0_dp, y0, rtol, [atol], st)
        call s%set_options()
        call t%check('options: start_bdf with nonstiff_only is refused', &
            st%code == LSODA_ERR_ILLEGAL_INPUT)
    end subroutine test_method_options

    !> Problems with exact solutions.
    subroutine test_exact(t)
        type(tester_t), intent(inout) :: t
        type(harmonic_t) :: osc
        type(linear_t) :: lin
        type(decay_t) :: dec
        type(lsoda_t) :: s
        type(status_t) :: stat
        type(integrator_stats_t) :: st
        real(dp) :: y(3), y2(2), y1(1), tt, ex(3), err
        real(dp), parameter :: touts(5) = [1.0e-4_dp, 1.0e-2_dp, 0.5_dp, 3.0_dp, 10.0_dp]
        integer :: k, ij
        character(len=40) :: nm

        ! harmonic oscillator, 50 periods, rtol = atol = 1e-9: global error grows ~ linearly;
        ! achieved 8.1e-7 at t = 100 pi
        call s%init(osc, 0.0_dp, [1.0_dp, 0.0_dp], 1.0e-9_dp, [1.0e-9_dp], stat)
        call t%check('harmonic: init', stat%code == STATUS_OK)
        err = 0.0_dp
        do k = 1, 100
            tt = k*pi
            call s%integrate(osc, tt, y2, stat)
            if (stat%code /= STATUS_OK) exit
            err = max(err, abs(y2(1) - cos(tt)), abs(y2(2) + sin(tt)))
        end do
        call t%check('harmonic: 50 periods without failure', stat%code == STATUS_OK)
        call t%check_close('harmonic: y1(100 pi) = 1', y2(1), 1.0_dp, atol=3.0e-6_dp)
        call t%check_close('harmonic: y2(100 pi) = 0', y2(2), 0.0_dp, atol=3.0e-6_dp)
        call t%check('harmonic: max error over the half periods < 3e-6', err < 3.0e-6_dp)
        st = s%stats()
        call t%check('harmonic: non-stiff, Adams only', st%method_switches == 0 .and. &
            st%method_last == METHOD_ADAMS .and. st%jac_evals == 0)

        ! linear stiff system y = V exp(lambda t) (V^-1 y0 = (1,1,1)), finite-difference and
        ! analytic Jacobian; rtol 1e-6, atol 1e-12 (anchor: scaled error ~ 20 at t = 10)
        do ij = 1, 2
            lin%use_jac = ij == 2
            nm = merge('linear (analytic J): ', 'linear (FD J):       ', lin%use_jac)
            call s%init(lin, 0.0_dp, [3.0_dp, 1.0_dp, 1.0_dp], 1.0e-6_dp, [1.0e-12_dp], stat)
            err = 0.0_dp
            do k = 1, 5
                tt = touts(k)
                call s%integrate(lin, tt, y, stat)
                if (stat%code /= STATUS_OK) exit
                ex = matmul(LIN_V, exp(LIN_LAM*tt))
                err = max(err, maxval(abs(y - ex)/(1.0e-12_dp + 1.0e-6_dp*abs(ex))))
            end do
            call t%check(trim(nm)//' no failure', stat%code == STATUS_OK)
            call t%check(trim(nm)//' scaled error < 60 at t = 1e-4 .. 10', err < 60.0_dp)
            call t%check_close(trim(nm)//' y1(10)', y(1), REF_LINEAR(1), rtol=6.0e-5_dp)
            st = s%stats()
            call t%check(trim(nm)//' switched to BDF and used Jacobians', &
                st%method_last == METHOD_BDF .and. st%jac_evals > 0 .and. &
                st%lu_decomps >= st%jac_evals .and. st%method_switches >= 1)
        end do

        ! y' = -y at t = 1
        call s%init(dec, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-12_dp], stat)
        call s%integrate(dec, 1.0_dp, y1, stat)
        call t%check('decay: no failure', stat%code == STATUS_OK)
        call t%check_close('decay: y(1) = exp(-1)', y1(1), exp(-1.0_dp), rtol=1.0e-7_dp)
        st = s%stats()
        call t%check('decay: stats consistent', st%steps > 0 .and. st%rhs_evals > st%steps &
            .and. st%t_current >= 1.0_dp .and. st%h_last > 0.0_dp)
        ! a tiny interval, y' = -1e278 y over [0, 1e-278]: y = exp(-1) (the first-step
        ! rule squared the interval: a division by zero, SIGFPE in the checking build, found
        ! by the fuzz test through a record of times in units of 1e-278 s)
        dec%k = 1.0e278_dp
        call s%init(dec, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-12_dp], stat)
        call s%integrate(dec, 1.0e-278_dp, y1, stat)
        call t%check('decay over [0, 1e-278]: no failure', stat%code == STATUS_OK)
        call t%check_close('decay over [0, 1e-278]: y = exp(-1)', y1(1), exp(-1.0_dp), &
                           rtol=1.0e-6_dp)
        dec%k = 1.0_dp
        ! backwards in time: y(-2) = exp(2)
        call s%init(dec, 0.0_dp, [1.0_dp], 1.0e-8_dp, [1.0e-12_dp], stat)
        call s%integrate(dec, -1.0_dp, y1, stat)
        call s%integrate(dec, -2.0_dp, y1, stat)
        st = s%stats()
        call t%check('decay backwards: no failure, h < 0', stat%code == STATUS_OK .and. &
            st%h_last < 0.0_dp .and. st%t_current <= -2.0_dp)
        call t%check_close('decay backwards: y(-2) = exp(2)', y1(1), exp(2.0_dp), rtol=1.0e-7_dp)
        ! hmax and h0 respected
        call s%init(dec, 0.0_dp, [1.0_dp], 1.0e-4_dp, [1.0e-8_dp], stat, h0=1.0e-6_dp, &
            hmax=0.01_dp)
        call s%step(dec, stat)
        st = s%stats()
        call t%check('h0: first step = h0', abs(st%h_last - 1.0e-6_dp) < 1.0e-20_dp)
        call s%integrate(dec, 1.0_dp, y1, stat)
        st = s%stats()
        call t%check('hmax: >= 100 steps over [0, 1] with hmax = 0.01', stat%code == STATUS_OK &
            .and. st%steps >= 100 .and. abs(st%h_last) <= 0.01_dp*(1.0_dp + 1.0e-12_dp))
        call t%check_close('hmax: y(1)', y1(1), exp(-1.0_dp), rtol=1.0e-3_dp)
    end subroutine test_exact

    !> The anchor problems against their reference values.
    subroutine test_problems(t)
        type(tester_t), intent(inout) :: t
        type(rober_t) :: rob
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: y3(3), err

        ! achieved scaled errors (ours = original LSODA's): rober 1e-6: 0.14, vdp1000 1e-6: 22,
        ! vdp1 1e-8: 41, arenstorf 1e-10: 4e4 (abs 4e-6), hires 1e-8: 5.2, pendulum 1e-10: 340
        call check_problem(t, 'rober', 1.0e-6_dp, 0.5_dp, st)
        call t%check('rober: ends in BDF, one switch', st%method_last == METHOD_BDF .and. &
            st%method_switches == 1)
        call check_problem(t, 'vdp1000', 1.0e-6_dp, 60.0_dp, st)
        call t%check('vdp1000: switches to BDF and back (>= 2 switches)', &
            st%method_switches >= 2)
        call check_problem(t, 'vdp1', 1.0e-8_dp, 100.0_dp, st)
        call t%check('vdp1: stays non-stiff', st%method_switches == 0 .and. st%jac_evals == 0)
        call check_problem(t, 'arenstorf', 1.0e-10_dp, 1.2e5_dp, st)
        call check_problem(t, 'hires', 1.0e-8_dp, 15.0_dp, st)
        call check_problem(t, 'pendulum', 1.0e-10_dp, 1000.0_dp, st)
        call check_problem(t, 'linear', 1.0e-7_dp, 120.0_dp, st)

        ! Robertson with the analytic Jacobian, and mass conservation
        rob%use_jac = .true.
        call solve_on_grid(rob, [1.0_dp, 0.0_dp, 0.0_dp], [0.0_dp, 0.4_dp, 4.0e3_dp, &
            4.0e7_dp, 4.0e10_dp], 1.0e-6_dp, 1.0e-6_dp*[1.0e-2_dp, 1.0e-6_dp, 1.0e-2_dp], &
            y3, st, stat)
        call t%check('rober (analytic J): no failure', stat%code == STATUS_OK)
        err = scaled_error(y3, REF_ROBER, 1.0e-6_dp, 1.0e-6_dp*[1.0e-2_dp, 1.0e-6_dp, 1.0e-2_dp])
        call t%check('rober (analytic J): scaled error < 1', err < 1.0_dp)
        call t%check_close('rober: y1+y2+y3 = 1', sum(y3), 1.0_dp, atol=1.0e-12_dp)
        call t%check('rober (analytic J): no f calls for Jacobians', &
            st%rhs_evals < 3*st%steps)
    end subroutine test_problems

    !> Solve bench problem `name` at rtol and check its scaled error at t_end <= bound.
    subroutine check_problem(t, name, rtol, bound, st)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: rtol, bound
        type(integrator_stats_t), intent(out) :: st
        class(ode_system_t), allocatable :: sys
        real(dp), allocatable :: y0(:), grid(:), atol(:), yref(:), y(:)
        type(status_t) :: stat
        real(dp) :: err
        character(len=80) :: buf
        call bench_problem(name, rtol, sys, y0, grid, atol, yref, stat)
        allocate (y(size(y0)))
        call solve_on_grid(sys, y0, grid, rtol, atol, y, st, stat)
        call t%check(name//': no failure', stat%code == STATUS_OK)
        err = scaled_error(y, yref, rtol, atol)
        write (buf, '(a,es9.2,a,es9.2,a,es9.2)') ': scaled error ', err, ' <= ', bound, &
            ' at rtol ', rtol
        call t%check(name//trim(buf), err <= bound)
    end subroutine check_problem

    !> The error shrinks with the tolerance.
    subroutine test_tolerance(t)
        type(tester_t), intent(inout) :: t
        type(harmonic_t) :: osc
        type(integrator_stats_t) :: st
        type(status_t) :: stat
        real(dp) :: rtol, y(2), err(8), nfe(8)
        integer :: k
        logical :: ok
        character(len=100) :: buf
        ! harmonic oscillator over 4 periods, rtol = atol = 1e-3 .. 1e-10; error measured
        ! against the exact solution in units of the tolerance
        do k = 1, 8
            rtol = 10.0_dp**(-(k + 2))
            call solve_on_grid(osc, [1.0_dp, 0.0_dp], [0.0_dp, 2.0_dp*pi, 4.0_dp*pi, &
                6.0_dp*pi, 8.0_dp*pi], rtol, [rtol], y, st, stat)
            err(k) = max(abs(y(1) - 1.0_dp), abs(y(2)))
            nfe(k) = st%rhs_evals
            call t%check('tolerance sweep: no failure', stat%code == STATUS_OK)
        end do
        ! error/tolerance stays within a factor 1 .. 150 (achieved 20 .. 62; global error of a
        ! local-error-per-step control over ~25 radians)
        do k = 1, 8
            rtol = 10.0_dp**(-(k + 2))
            write (buf, '(a,es8.1,a,es9.2)') 'tolerance sweep: error/rtol in [1, 150] at rtol ', &
                rtol, ': ', err(k)/rtol
            call t%check(trim(buf), err(k)/rtol <= 150.0_dp .and. err(k)/rtol >= 1.0_dp)
        end do
        ! decreases: every two decades of tolerance at least one decade of error, and
        ! never grows by more than a factor 3 from one decade to the next
        ok = .true.
        do k = 1, 6
            ok = ok .and. err(k + 2) < 0.1_dp*err(k)
        end do
        call t%check('tolerance sweep: error drops >= 10x per two decades of rtol', ok)
        ok = .true.
        do k = 1, 7
            ok = ok .and. err(k + 1) < 3.0_dp*err(k) .and. nfe(k + 1) > nfe(k)
        end do
        call t%check('tolerance sweep: monotone-ish error, work grows', ok)
        call t%check('tolerance sweep: 7 decades of rtol give >= 5 decades of error', &
            err(8) < 1.0e-5_dp*err(1))
    end subroutine test_tolerance

    !> Every failure code, from a deliberate case.
    subroutine test_failures(t)
        type(tester_t), intent(inout) :: t
        type(vdp_t) :: vdp
        type(decay_t) :: dec
        type(jump_t) :: jmp
        type(wild_t) :: wild
        type(singular_t) :: sng
        type(failing_t) :: fl
        type(lsoda_t) :: s, fresh
        type(status_t) :: stat
        type(integrator_stats_t) :: st
        real(dp) :: y2(2), y3(3), y1(1)

        ! too many steps
        call s%init(vdp, 0.0_dp, [2.0_dp, 0.0_dp], 1.0e-6_dp, [1.0e-9_dp], stat, max_steps=10)
        call s%integrate(vdp, 3000.0_dp, y2, stat)
        st = s%stats()
        call t%check('max steps: code', stat%code == LSODA_ERR_MAX_STEPS)
        call t%check('max steps: message', has_msg(stat, 'steps'))
        call t%check('max steps: 10 steps, stopped inside', st%steps == 10 .and. &
            st%t_current > 0.0_dp .and. st%t_current < 3000.0_dp)
        call t%check('max steps: y = state at t_current, finite', all(ieee_is_finite(y2)) &
            .and. abs(y2(1) - 2.0_dp) < 0.1_dp)
        ! the integration goes on with the next call (another 10 steps)
        call s%integrate(vdp, 3000.0_dp, y2, stat)
        call t%check('max steps: continues on the next call', &
            stat%code == LSODA_ERR_MAX_STEPS .and. count_steps(s) == 20)

        ! too much accuracy
        call s%init(dec, 0.0_dp, [1.0_dp], 1.0e-300_dp, [1.0e-300_dp], stat)
        call s%integrate(dec, 1.0_dp, y1, stat)
        st = s%stats()
        call t%check('too much accuracy: code', stat%code == LSODA_ERR_TOO_MUCH_ACCURACY)
        call t%check('too much accuracy: message', has_msg(stat, 'accuracy'))
        call t%check('too much accuracy: y kept', y1(1) == 1.0_dp .and. st%t_current == 0.0_dp)
        ! ... also when it happens on the way (pure relative control, y -> 1e-320 region)
        call s%init(dec, 0.0_dp, [1.0_dp], 1.0e-15_dp, [0.0_dp], stat)
        call s%integrate(dec, 1.0_dp, y1, stat)
        call t%check('too much accuracy (rtol 1e-15): code', &
            stat%code == LSODA_ERR_TOO_MUCH_ACCURACY)

        ! repeated error-test failures: f jumps to 1e100 at t = 1
        call s%init(jmp, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call s%integrate(jmp, 2.0_dp, y1, stat)
        st = s%stats()
        call t%check('error test: code', stat%code == LSODA_ERR_ERROR_TEST)
        call t%check('error test: message names t', has_msg(stat, 'error test') .and. &
            has_msg(stat, 't ='))
        call t%check('error test: stopped at the jump', st%t_current <= 1.0_dp .and. &
            st%t_current > 0.99_dp)
        call t%check('error test: the failures are counted (>= 3)', &
            st%error_test_failures >= 3)
        call t%check_close('error test: y = exp(-t_current)', y1(1), exp(-st%t_current), &
            rtol=1.0e-4_dp)

        ! repeated convergence failures: f = 1e8 sin(1e9 y) after t = 1
        call s%init(wild, 0.0_dp, [1.0_dp, 0.5_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call s%integrate(wild, 2.0_dp, y2, stat)
        st = s%stats()
        call t%check('convergence: code', stat%code == LSODA_ERR_CONVERGENCE)
        call t%check('convergence: message', has_msg(stat, 'converge'))
        call t%check('convergence: stopped at t = 1', abs(st%t_current - 1.0_dp) < 1.0e-9_dp &
            .and. all(ieee_is_finite(y2)))
        call t%check('convergence: the failures are counted (>= 2)', st%conv_failures >= 2)
        call t%check_close('convergence: y = exp(-t_current)', y2(1), exp(-st%t_current), &
            rtol=1.0e-4_dp)

        ! singular iteration matrix: the Jacobian becomes 1e200*ones after t = 1
        call s%init(sng, 0.0_dp, [1.0_dp, 1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call s%integrate(sng, 2.0_dp, y2, stat)
        st = s%stats()
        call t%check('singular: code', stat%code == LSODA_ERR_SINGULAR)
        call t%check('singular: message', has_msg(stat, 'singular'))
        ! (the old matrix serves a few steps past t = 1 before the new one is formed)
        call t%check('singular: in BDF, stopped soon after t = 1', &
            st%method_next == METHOD_BDF .and. st%t_current > 1.0_dp .and. st%t_current < 2.0_dp)
        call t%check('singular: y ~ cos(t_current)', all(abs(y2 - cos(st%t_current)) < 1.0e-3_dp))

        ! the right-hand side's own status is passed through
        call s%init(fl, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call s%integrate(fl, 3.0_dp, y1, stat)
        st = s%stats()
        call t%check('rhs status: code passed through', stat%code == 42)
        call t%check('rhs status: message kept, time prefixed', &
            has_msg(stat, 'model left its domain') .and. has_msg(stat, 'at t ='))
        call t%check('rhs status: stopped before t = 1', st%t_current <= 1.0_dp)
        call t%check_close('rhs status: y = exp(-t_current)', y1(1), exp(-st%t_current), &
            rtol=1.0e-4_dp)
        ! ... also from init
        fl%t_bad = -1.0_dp
        call s%init(fl, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call t%check('rhs status: from init', stat%code == 42)

        ! illegal input
        call s%init(dec, 0.0_dp, [1.0_dp, 2.0_dp, 3.0_dp], -1.0e-6_dp, [1.0e-8_dp], stat)
        call t%check('illegal: rtol < 0', stat%code == LSODA_ERR_ILLEGAL_INPUT .and. &
            has_msg(stat, 'rtol'))
        call s%init(dec, 0.0_dp, [1.0_dp, 2.0_dp, 3.0_dp], 1.0e-6_dp, &
            [1.0e-8_dp, -1.0_dp, 1.0_dp], stat)
        call t%check('illegal: atol < 0', stat%code == LSODA_ERR_ILLEGAL_INPUT .and. &
            has_msg(stat, 'atol'))
        call s%init(dec, 0.0_dp, [1.0_dp, 2.0_dp, 3.0_dp], 1.0e-6_dp, [1.0_dp, 1.0_dp], stat)
        call t%check('illegal: size(atol) not 1 or n', stat%code == LSODA_ERR_ILLEGAL_INPUT &
            .and. has_msg(stat, 'size(atol)'))
        call fresh%integrate(dec, 1.0_dp, y3, stat)
        call t%check('illegal: integrate before init', stat%code == LSODA_ERR_ILLEGAL_INPUT)
        call s%init(dec, 0.0_dp, [1.0_dp, 2.0_dp, 3.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call s%integrate(dec, 1.0_dp, y2, stat)
        call t%check('illegal: size(y) /= n', stat%code == LSODA_ERR_ILLEGAL_INPUT)
        call s%integrate(dec, 1.0_dp, y3, stat)
        call s%integrate(dec, 0.5_dp, y3, stat)
        call t%check('illegal: tout behind t', stat%code == LSODA_ERR_ILLEGAL_INPUT .and. &
            has_msg(stat, 'behind'))
        call s%init(dec, 0.0_dp, [1.0_dp, 2.0_dp, 3.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat, &
            tcrit=0.5_dp)
        call s%integrate(dec, 1.0_dp, y3, stat)
        call t%check('illegal: tcrit behind tout', stat%code == LSODA_ERR_ILLEGAL_INPUT .and. &
            has_msg(stat, 'tcrit'))
        call s%set_options(max_order_bdf=6)
        call s%init(dec, 0.0_dp, [1.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat)
        call s%set_options()
        call t%check('illegal: max_order_bdf = 6', stat%code == LSODA_ERR_ILLEGAL_INPUT)
        call s%init(dec, 0.0_dp, [0.0_dp], 1.0e-6_dp, [0.0_dp], stat)
        call s%integrate(dec, 1.0_dp, y1, stat)
        call t%check('illegal: zero error weight', stat%code == LSODA_ERR_ILLEGAL_INPUT)
    end subroutine test_failures

    integer function count_steps(s)
        type(lsoda_t), intent(in) :: s
        type(integrator_stats_t) :: st
        st = s%stats()
        count_steps = st%steps
    end function count_steps

    logical function has_msg(stat, part)
        type(status_t), intent(in) :: stat
        character(len=*), intent(in) :: part
        has_msg = .false.
        if (allocated(stat%msg)) has_msg = index(stat%msg, part) > 0
    end function has_msg

    !> Two solvers interleaved give bit-identical results to separate runs.
    subroutine test_interleave(t)
        type(tester_t), intent(inout) :: t
        type(vdp_t) :: va, vb
        type(rober_t) :: rb
        type(lsoda_t) :: s1, s2
        type(status_t) :: st1, st2
        type(integrator_stats_t) :: a1, a2, b1, b2
        real(dp) :: ya(2), yb(3), ya_sep(2), yb_sep(3), grid(13)
        integer :: k
        logical :: same
        va%mu = 1000.0_dp
        vb%mu = 1000.0_dp
        grid(1) = 0.0_dp
        do k = 0, 11
            grid(k + 2) = 0.4_dp*10.0_dp**k
        end do
        ! separately
        call s1%init(va, 0.0_dp, [2.0_dp, 0.0_dp], 1.0e-5_dp, [1.0e-8_dp], st1)
        do k = 1, 12
            call s1%integrate(va, 250.0_dp*k, ya_sep, st1)
        end do
        a1 = s1%stats()
        call s2%init(rb, 0.0_dp, [1.0_dp, 0.0_dp, 0.0_dp], 1.0e-5_dp, &
            1.0e-5_dp*[1.0e-2_dp, 1.0e-6_dp, 1.0e-2_dp], st2)
        do k = 2, 13
            call s2%integrate(rb, grid(k), yb_sep, st2)
        end do
        b1 = s2%stats()
        ! interleaved (fresh objects of the same types)
        call s1%init(vb, 0.0_dp, [2.0_dp, 0.0_dp], 1.0e-5_dp, [1.0e-8_dp], st1)
        call s2%init(rb, 0.0_dp, [1.0_dp, 0.0_dp, 0.0_dp], 1.0e-5_dp, &
            1.0e-5_dp*[1.0e-2_dp, 1.0e-6_dp, 1.0e-2_dp], st2)
        same = .true.
        do k = 1, 12
            call s1%integrate(vb, 250.0_dp*k, ya, st1)
            call s2%integrate(rb, grid(k + 1), yb, st2)
            same = same .and. st1%code == STATUS_OK .and. st2%code == STATUS_OK
        end do
        a2 = s1%stats()
        b2 = s2%stats()
        call t%check('interleave: both succeed', same)
        call t%check('interleave: vdp identical', all(ya == ya_sep) .and. &
            a1%steps == a2%steps .and. a1%rhs_evals == a2%rhs_evals .and. &
            a1%jac_evals == a2%jac_evals .and. a1%method_switches == a2%method_switches)
        call t%check('interleave: rober identical', all(yb == yb_sep) .and. &
            b1%steps == b2%steps .and. b1%rhs_evals == b2%rhs_evals .and. &
            b1%jac_evals == b2%jac_evals)
    end subroutine test_interleave

    !> Dense output inside steps against the exact solution; tcrit never overstepped.
    subroutine test_dense_tcrit(t)
        type(tester_t), intent(inout) :: t
        type(harmonic_t) :: osc
        type(guard_t) :: g
        type(lsoda_t) :: s
        type(status_t) :: stat
        type(integrator_stats_t) :: st
        real(dp) :: d(2), tt, ta, tb, err0, err1, y1(1)
        integer :: k, j
        logical :: ok

        ! dense output of the oscillator: value and first derivative at 5 points per step
        call s%init(osc, 0.0_dp, [1.0_dp, 0.0_dp], 1.0e-8_dp, [1.0e-8_dp], stat)
        err0 = 0.0_dp
        err1 = 0.0_dp
        ok = .true.
        do k = 1, 200
            call s%step(osc, stat, tout=10.0_dp)
            if (stat%code /= STATUS_OK) exit
            st = s%stats()
            tb = st%t_current
            ta = tb - st%h_last
            do j = 0, 4
                tt = ta + (tb - ta)*j/4.0_dp
                call s%dense(tt, 0, d, stat)
                ok = ok .and. stat%code == STATUS_OK
                err0 = max(err0, abs(d(1) - cos(tt)), abs(d(2) + sin(tt)))
                call s%dense(tt, 1, d, stat)
                ok = ok .and. stat%code == STATUS_OK
                err1 = max(err1, abs(d(1) + sin(tt)), abs(d(2) + cos(tt)))
            end do
            if (tb > 10.0_dp) exit
        end do
        call t%check('dense: steps and dense calls succeed', ok .and. stat%code == STATUS_OK)
        call t%check('dense: reached t = 10 by single steps', tb > 10.0_dp)
        ! global error at rtol 1e-8 over 10 radians is ~1e-7; the interpolant adds less
        call t%check('dense: y between steps within 1e-6 of exact', err0 < 1.0e-6_dp)
        call t%check('dense: y'' between steps within 1e-4 of exact', err1 < 1.0e-4_dp)
        call s%dense(tb + 1.0_dp, 0, d, stat)
        call t%check('dense: t outside the last step rejected', &
            stat%code == LSODA_ERR_ILLEGAL_INPUT)
        call s%dense(tb, 20, d, stat)
        call t%check('dense: k > order rejected', stat%code == LSODA_ERR_ILLEGAL_INPUT)

        ! tcrit: integrate to outputs below and at tcrit, rhs records any t > tcrit
        g%tcrit = 1.0_dp
        g%violations = 0
        call s%init(g, 0.0_dp, [0.0_dp], 1.0e-6_dp, [1.0e-8_dp], stat, tcrit=1.0_dp)
        call s%integrate(g, 0.3_dp, y1, stat)
        call s%integrate(g, 0.999_dp, y1, stat)
        call s%integrate(g, 1.0_dp, y1, stat)
        st = s%stats()
        call t%check('tcrit: reached', stat%code == STATUS_OK .and. &
            abs(st%t_current - 1.0_dp) < 1.0e-12_dp)
        call t%check('tcrit: f never evaluated past tcrit', g%violations == 0)
        ! exact: y = (sin t + cos t - exp(-t))/2
        call t%check_close('tcrit: y(1)', y1(1), 0.5_dp*(sin(1.0_dp) + cos(1.0_dp) - &
            exp(-1.0_dp)), rtol=1.0e-5_dp)
        call s%step(g, stat)
        call t%check('tcrit: step at tcrit refused', stat%code == LSODA_ERR_ILLEGAL_INPUT)
        ! move tcrit on with single steps
        g%tcrit = 2.5_dp
        call s%set_tcrit(2.5_dp, stat)
        ok = stat%code == STATUS_OK
        do k = 1, 10000
            call s%step(g, stat)
            if (stat%code /= STATUS_OK) exit
            st = s%stats()
            if (abs(st%t_current - 2.5_dp) < 1.0e-12_dp) exit
        end do
        call t%check('tcrit: single steps stop exactly at the new tcrit', ok .and. &
            stat%code == STATUS_OK .and. abs(st%t_current - 2.5_dp) < 1.0e-12_dp)
        call t%check('tcrit: still never past tcrit', g%violations == 0)
        ! remove tcrit: free to step on
        call s%set_tcrit()
        g%tcrit = huge(1.0_dp)
        call s%integrate(g, 4.0_dp, y1, stat)
        st = s%stats()
        call t%check('tcrit removed: integrates past the old tcrit', stat%code == STATUS_OK &
            .and. st%t_current >= 4.0_dp)
        call t%check_close('tcrit removed: y(4)', y1(1), 0.5_dp*(sin(4.0_dp) + cos(4.0_dp) - &
            exp(-4.0_dp)), rtol=1.0e-4_dp)
        ! tcrit given before the first step bounds the first step too
        g%tcrit = 1.0e-3_dp
        g%violations = 0
        call s%init(g, 0.0_dp, [0.0_dp], 1.0e-3_dp, [1.0e-3_dp], stat, tcrit=1.0e-3_dp)
        call s%integrate(g, 1.0e-3_dp, y1, stat)
        call t%check('tcrit: tiny tcrit respected from the first step', &
            stat%code == STATUS_OK .and. g%violations == 0)
    end subroutine test_dense_tcrit

end module test_lsoda
