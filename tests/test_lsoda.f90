!> Tests of module lsoda and the benchmark problems they share with bench_integrator.
!!
!! Problems (definitions, tolerance rules, output grids and reference values exactly as in
!! the anchors, shared/reference/integrator/anchors.md):
!! rober (Robertson), vdp (Van der Pol, parameter mu), arenstorf, hires, pendulum
!! (theta'' = -sin theta), linear (3x3 stiff, eigenvalues -1, -1e3, -1e6), plus a harmonic
!! oscillator and exponential decay with exact solutions.  None counts anything: the
!! solver's stats() do.
module test_lsoda
    use kinds, only: dp, pi
    use status, only: status_t, set_error, STATUS_OK
    use ode_system, only: ode_system_t
    use lsoda, only: lsoda_t, lsoda_stats_t, METHOD_ADAMS, METHOD_BDF, LSODA_ERR_MAX_STEPS, &
        LSODA_ERR_TOO_MUCH_ACCURACY, LSODA_ERR_ERROR_TEST, LSODA_ERR_CONVERGENCE, &
        LSODA_ERR_ILLEGAL_INPUT, LSODA_ERR_SINGULAR
    use testing, only: tester_t
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
        a = RK1*y(1)
        b = RK3*y(2)*y(3)
        c = RK2*y(2)*y(2)
        ydot(1) = -a + b
        ydot(2) = a - b - c
        ydot(3) = c
        stat%code = STATUS_OK
        if (.false.) ydot(1) = t + merge(1.0_dp, 0.0_dp, sys%use_jac)
    end subroutine rober_rhs

    subroutine rober_jac(sys, t, y, dfdy, stat)
        class(rober_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        dfdy(1, :) = [-RK1, RK3*y(3), RK3*y(2)]
        dfdy(2, :) = [RK1, -RK3*y(3) - 2.0_dp*RK2*y(2), -RK3*y(2)]
        dfdy(3, :) = [0.0_dp, 2.0_dp*RK2*y(2), 0.0_dp]
        stat%code = STATUS_OK
        if (.false.) dfdy(1, 1) = t + merge(1.0_dp, 0.0_dp, sys%use_jac)
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
        ydot(1) = y(2)
        ydot(2) = sys%mu*(1.0_dp - y(1)*y(1))*y(2) - y(1)
        stat%code = STATUS_OK
        if (.false.) ydot(1) = t
    end subroutine vdp_rhs

    subroutine arenstorf_rhs(sys, t, y, ydot, stat)
        class(arenstorf_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: d1, d2
        d1 = ((y(1) + AM)**2 + y(2)**2)**1.5_dp
        d2 = ((y(1) - AMP)**2 + y(2)**2)**1.5_dp
        ydot(1) = y(3)
        ydot(2) = y(4)
        ydot(3) = y(1) + 2.0_dp*y(4) - AMP*(y(1) + AM)/d1 - AM*(y(1) - AMP)/d2
        ydot(4) = y(2) - 2.0_dp*y(3) - AMP*y(2)/d1 - AM*y(2)/d2
        stat%code = STATUS_OK
        if (.false.) ydot(1) = t + merge(1.0_dp, 0.0_dp, same_type_as(sys, sys))
    end subroutine arenstorf_rhs

    subroutine hires_rhs(sys, t, y, ydot, stat)
        class(hires_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        real(dp) :: p
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
        if (.false.) ydot(1) = t + merge(1.0_dp, 0.0_dp, same_type_as(sys, sys))
    end subroutine hires_rhs

    subroutine pendulum_rhs(sys, t, y, ydot, stat)
        class(pendulum_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        ydot(1) = y(2)
        ydot(2) = -sin(y(1))
        stat%code = STATUS_OK
        if (.false.) ydot(1) = t + merge(1.0_dp, 0.0_dp, same_type_as(sys, sys))
    end subroutine pendulum_rhs

    subroutine linear_rhs(sys, t, y, ydot, stat)
        class(linear_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        ydot(1) = LIN_A(1, 1)*y(1) + LIN_A(1, 2)*y(2) + LIN_A(1, 3)*y(3)
        ydot(2) = LIN_A(2, 1)*y(1) + LIN_A(2, 2)*y(2) + LIN_A(2, 3)*y(3)
        ydot(3) = LIN_A(3, 1)*y(1) + LIN_A(3, 2)*y(2) + LIN_A(3, 3)*y(3)
        stat%code = STATUS_OK
        if (.false.) ydot(1) = t + merge(1.0_dp, 0.0_dp, sys%use_jac)
    end subroutine linear_rhs

    subroutine linear_jac(sys, t, y, dfdy, stat)
        class(linear_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        dfdy = LIN_A
        stat%code = STATUS_OK
        if (.false.) dfdy(1, 1) = t + y(1) + merge(1.0_dp, 0.0_dp, sys%use_jac)
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
        ydot(1) = sys%omega*y(2)
        ydot(2) = -sys%omega*y(1)
        stat%code = STATUS_OK
        if (.false.) ydot(1) = t
    end subroutine harmonic_rhs

    subroutine decay_rhs(sys, t, y, ydot, stat)
        class(decay_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(status_t), intent(out) :: stat
        ydot = -sys%k*y
        stat%code = STATUS_OK
        if (.false.) ydot(1) = t
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
        ydot = -1.0e4_dp*(y - cos(t))
        stat%code = STATUS_OK
        if (.false.) ydot(1) = sys%t_bad
    end subroutine singular_rhs

    subroutine singular_jac(sys, t, y, dfdy, stat)
        class(singular_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: dfdy(:, :)
        type(status_t), intent(out) :: stat
        if (t <= sys%t_bad) then
            dfdy = 0.0_dp
            dfdy(1, 1) = -1.0e4_dp
            dfdy(2, 2) = -1.0e4_dp
        else
            ! h*l0*J dwarfs I: P = I - h*l0*J rounds to -c*[[1,1],[1,1]], exactly singular
            dfdy = 1.0e200_dp
        end if
        stat%code = STATUS_OK
        if (.false.) dfdy(1, 1) = y(1)
    end subroutine singular_jac

    logical function singular_has_jac(sys)
        class(singular_t), intent(in) :: sys
        singular_has_jac = .true.
        if (.false.) singular_has_jac = sys%t_bad > 0.0_dp
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
        type(lsoda_stats_t), intent(out) :: st
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
    subroutine run_lsoda_tests(t)
        type(tester_t), intent(inout) :: t
    end subroutine run_lsoda_tests

end module test_lsoda
