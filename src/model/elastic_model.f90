!> The bifilar pendulum with elastic cables, in maximal coordinates.
!!
!! A second model of the same rig, written in different coordinates from the paper's (an
!! independent check of eqs. (37)-(43)) and able to represent what the paper's model cannot:
!! cables that stretch, carry internal damping and go slack.
!!
!! Scaled units as everywhere in bifilar: lengths over b', mass over m, time tau =
!! sqrt(g/b') t, forces over m g, energies over m g b'.  n3 points up, A is the origin,
!! B = (0, -B, 0).  The body frame is the paper's ntilde (eq. (8)): C is the body point at
!! the origin of ntilde, D = C - ntilde3, R* = C + r (sin(lambda) ntilde1 - cos(lambda) ntilde3)
!! (eqs. (21)-(22)), principal axes b_i = sum_j btilde(i,j) ntilde_j with moments I_i.
!!
!! State (ELASTIC_NSTATE = 13):
!!   y(1:3)   R*, the mass centre, in n components
!!   y(4:6)   its velocity
!!   y(7:10)  unit quaternion (w, x, y, z) of the rotation taking ntilde to the body's pose:
!!            ntilde_i = R(:, i) in n components, R the usual (Hamilton) rotation matrix,
!!            so the direction cosines of eq. (8) are n(i, j) = R(j, i)
!!   y(11:13) angular velocity in ntilde components (omega . ntilde_i)
!! The rotation matrix is always built from q/|q| (so a drifting norm never distorts the
!! body), and qdot carries a norm-stabilising term a (1 - |q|^2) q (a = quat_rate, 1 per
!! unit tau), which vanishes on the exact motion.
!!
!! Cables (index 1 = BC, from B to the body point C; index 2 = AD, from A to D).  Each is a
!! massless spring-dashpot along the straight line support -> body point:
!!   natural (unstretched) lengths L0: by default the deck's l/b' and l'/b'; elastic_start
!!   instead takes the deck's lengths as the loaded lengths at the start, L0 = l/(1 + T0/k)
!!   with T0 the paper model's tension at the start state, so the elastic start has the
!!   inextensible start's pose, velocities, tensions and accelerations and no stretching
!!   transient is excited.  Either way L0 -> l as k -> infinity and stiff cables converge to
!!   the paper's inextensible model, the difference O(1/k);
!!   strain eps = (|s| - L0)/L0;  stiffness k = EA/(m g) (nondimensional, per cable);
!!   damping: a damping ratio zeta per cable relative to critical for the whole mass m on
!!   that cable's spring (spring constant EA/L0): dashpot coefficient
!!   c = 2 zeta sqrt(EA m/L0), i.e. c = 2 zeta sqrt(k/L0) in m g per (b' per unit tau);
!!   tension T = max(0, k eps + c d|s|/dtau) when eps > 0, T = 0 when eps <= 0 (slack: the
!!   cable neither pushes nor damps);  the cable pulls the body point towards the support
!!   with force -T s/|s|;  spring energy (1/2) k L0 eps^2 for eps > 0, 0 otherwise.
!! Slack is a state of this model, not an error.  The law above has a kink where a cable
!! goes slack, and a Newton iteration of an implicit method that crosses the kink fails to
!! converge (at k = 1e8 the static stretch, 1e-8, lies within the position tolerance, so
!! the iterates cross it all the time).  Each cable therefore carries a mode (elastic_t%mode):
!!   CABLE_AUTO   the law above, decided at every evaluation (the default; for explicit
!!                methods and for reporting)
!!   CABLE_TAUT   T = k eps + c d|s|/dtau, the smooth linear spring-dashpot on both sides
!!   CABLE_SLACK  T = 0
!! and the switching function g = min(k eps, k eps + c d|s|/dtau) (cable_switch) says which
!! mode the law above is in: taut when g > 0.  module elastic_solver keeps the modes, locates
!! the zeros of g in the integrator's dense output and restarts there, so every step of the
!! implicit method sees a smooth right-hand side and the modes agree with the law above at
!! every step end.  Tensions, strains and slack flags are reported (elastic_cables_t).
!!
!! The body: m R*'' = -m g n3 + F_BC + F_AD;  Euler's equations in ntilde components,
!! I omega' + omega x I omega = sum (r_P x F_P), I = btilde^T diag(I_i) btilde.
module elastic_model
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_NUMERIC, STATUS_OK
    use ode_system, only: ode_system_t
    use geometry, only: pendulum_t, direction_cosines, cable_direction, body_axes
    use kinematics, only: omega_coeffs
    use vectors, only: cross
    use gen_forces, only: inertia_dyadic
    use bifilar_model, only: motion_t, chart_state, paper_angles, evaluate
    use unused_arg, only: unused
    implicit none
    private

    integer, parameter, public :: ELASTIC_NSTATE = 13  !! y = (R*, v*, q, omega_body)
    integer, parameter, public :: CABLE_BC = 1, CABLE_AD = 2
    !> Cable modes (elastic_t%mode): the law decided at each evaluation, taut, slack.
    integer, parameter, public :: CABLE_AUTO = 0, CABLE_TAUT = 1, CABLE_SLACK = 2

    !> The elastic pendulum as an ODE system for the integrator.
    type, extends(ode_system_t), public :: elastic_t
        type(pendulum_t) :: p                   !! scaled parameters (stab_rate is not used)
        real(dp) :: stiffness = 1.0e6_dp        !! k = EA/(m g) of each cable (nondimensional)
        real(dp) :: damping = 0.0_dp            !! zeta: damping ratio of each cable (see above)
        real(dp) :: quat_rate = 1.0_dp          !! a: rate of the quaternion-norm stabilisation
        real(dp) :: l0(2) = -1.0_dp             !! natural lengths of BC, AD over b'; <= 0: the
                                                !! deck's l/b', l'/b' (see elastic_start)
        integer :: mode(2) = CABLE_AUTO         !! CABLE_AUTO, CABLE_TAUT or CABLE_SLACK per cable
    contains
        procedure :: rhs => elastic_rhs
        procedure :: jacobian => elastic_jacobian
        procedure :: has_jacobian => elastic_has_jacobian
    end type elastic_t

    !> The cables at one instant (index CABLE_BC = 1, CABLE_AD = 2).
    type, public :: elastic_cables_t
        real(dp) :: tension(2) = 0.0_dp         !! over m g; 0 when slack
        real(dp) :: strain(2) = 0.0_dp          !! (|s| - L0)/L0; <= 0 when slack
        real(dp) :: length(2) = 0.0_dp          !! |s| over b'
        real(dp) :: length_rate(2) = 0.0_dp     !! d|s|/dtau
        logical :: slack(2) = .false.           !! strain <= 0, or the dashpot would push
        real(dp) :: spring_energy = 0.0_dp      !! sum of (1/2) k L0 eps^2 over m g b'
    end type elastic_cables_t

    public :: elastic_from_chart, elastic_from_angles, elastic_evaluate, elastic_chart
    public :: elastic_energy, elastic_pose, quat_to_matrix, matrix_to_quat, elastic_start
    public :: natural_lengths, elastic_atol, cable_switch, stretch_frequency
    public :: elastic_rhs_stretched, cable_switch_stretched

contains

    ! ------------------------------------------------------------------------------------
    ! Body geometry in ntilde components
    ! ------------------------------------------------------------------------------------

    !> C - R* in ntilde components: -r (sin(lambda), 0, -cos(lambda)).
    pure function body_c(p) result(rb)
        type(pendulum_t), intent(in) :: p
        real(dp) :: rb(3)
        rb = [-p%r*sin(p%lambda), 0.0_dp, p%r*cos(p%lambda)]
    end function body_c

    !> Inertia of the body for R* in ntilde components, and its inverse.
    pure subroutine body_inertia(p, ib, ibinv)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(out) :: ib(3, 3), ibinv(3, 3)
        ib = inertia_dyadic(p%btilde, p%inertia)
        ibinv = inertia_dyadic(p%btilde, 1.0_dp/p%inertia)
    end subroutine body_inertia

    !> Rotation matrix of the quaternion q/|q| (w, x, y, z): body components -> n components.
    pure function quat_to_matrix(q) result(r)
        real(dp), intent(in) :: q(4)
        real(dp) :: r(3, 3)
        real(dp) :: s, w, x, y, z
        s = 2.0_dp/dot_product(q, q)
        w = q(1); x = q(2); y = q(3); z = q(4)
        r(1, :) = [1.0_dp - s*(y*y + z*z), s*(x*y - w*z), s*(x*z + w*y)]
        r(2, :) = [s*(x*y + w*z), 1.0_dp - s*(x*x + z*z), s*(y*z - w*x)]
        r(3, :) = [s*(x*z - w*y), s*(y*z + w*x), 1.0_dp - s*(x*x + y*y)]
    end function quat_to_matrix

    !> Unit quaternion (w >= 0) of a rotation matrix (Shepperd's method).
    pure function matrix_to_quat(r) result(q)
        real(dp), intent(in) :: r(3, 3)
        real(dp) :: q(4)
        real(dp) :: tr, f
        integer :: k
        tr = r(1, 1) + r(2, 2) + r(3, 3)
        k = maxloc([tr, r(1, 1), r(2, 2), r(3, 3)], 1)
        select case (k)
        case (1)
            f = sqrt(1.0_dp + tr)
            q = [0.5_dp*f, 0.5_dp*(r(3, 2) - r(2, 3))/f, 0.5_dp*(r(1, 3) - r(3, 1))/f, &
                 0.5_dp*(r(2, 1) - r(1, 2))/f]
        case (2)
            f = sqrt(1.0_dp + r(1, 1) - r(2, 2) - r(3, 3))
            q = [0.5_dp*(r(3, 2) - r(2, 3))/f, 0.5_dp*f, 0.5_dp*(r(1, 2) + r(2, 1))/f, &
                 0.5_dp*(r(1, 3) + r(3, 1))/f]
        case (3)
            f = sqrt(1.0_dp - r(1, 1) + r(2, 2) - r(3, 3))
            q = [0.5_dp*(r(1, 3) - r(3, 1))/f, 0.5_dp*(r(1, 2) + r(2, 1))/f, 0.5_dp*f, &
                 0.5_dp*(r(2, 3) + r(3, 2))/f]
        case default
            f = sqrt(1.0_dp - r(1, 1) - r(2, 2) + r(3, 3))
            q = [0.5_dp*(r(2, 1) - r(1, 2))/f, 0.5_dp*(r(1, 3) + r(3, 1))/f, &
                 0.5_dp*(r(2, 3) + r(3, 2))/f, 0.5_dp*f]
        end select
        if (q(1) < 0.0_dp) q = -q
        q = q/norm2(q)
    end function matrix_to_quat

    !> Positions and velocities of C, D and E and the body's frame at an elastic state.
    !! n(i, :) = ntilde_i in n components (eq. (8)); omega in n components.
    pure subroutine elastic_pose(p, y, c, d, e, vc, vd, n, omega)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp), intent(out) :: c(3), d(3), e(3), vc(3), vd(3), n(3, 3), omega(3)
        real(dp) :: r(3, 3), rc(3), rd(3)
        r = quat_to_matrix(y(7:10))
        n = transpose(r)
        omega = matmul(r, y(11:13))
        rc = matmul(r, body_c(p))
        rd = rc - r(:, 3)
        c = y(1:3) + rc
        d = y(1:3) + rd
        e = c - 0.5_dp*r(:, 3) + p%h_e*r(:, 1)
        vc = y(4:6) + cross(omega, rc)
        vd = y(4:6) + cross(omega, rd)
    end subroutine elastic_pose

    !> Dashpot coefficient c = 2 zeta sqrt(k/L0) of a cable of natural length l0.
    pure real(dp) function dashpot(sys, l0)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: l0
        dashpot = 2.0_dp*sys%damping*sqrt(sys%stiffness/l0)
    end function dashpot

    !> One cable in mode `mode`: support point s0, body point x with velocity v, natural
    !! length l0.  Force on the body point and the cable's state.  given(1:2) > -1: the
    !! stretch |s| - l0 and its rate as known (elastic_gen, where they are states), used
    !! for the tension instead of their values from x and v (the same up to roundoff; at
    !! k = 1e8 the roundoff of |s| - l0 alone is 1e-8 of the weight).
    pure subroutine cable(sys, mode, s0, x, v, l0, f, tension, strain, length, rate, slack, &
                          energy, given)
        type(elastic_t), intent(in) :: sys
        integer, intent(in) :: mode             !! CABLE_AUTO, CABLE_TAUT or CABLE_SLACK
        real(dp), intent(in) :: s0(3), x(3), v(3), l0
        real(dp), intent(out) :: f(3), tension, strain, length, rate, energy
        logical, intent(out) :: slack
        real(dp), intent(in), optional :: given(2)  !! stretch and stretch rate
        real(dp) :: s(3), u(3)
        s = x - s0
        length = norm2(s)
        u = s/length
        rate = dot_product(u, v)
        strain = (length - l0)/l0
        if (present(given)) then
            strain = given(1)/l0
            length = l0 + given(1)
            rate = given(2)
        end if
        tension = 0.0_dp
        energy = 0.0_dp
        if (strain > 0.0_dp) energy = 0.5_dp*sys%stiffness*l0*strain**2
        select case (mode)
        case (CABLE_TAUT)
            tension = sys%stiffness*strain + dashpot(sys, l0)*rate
            energy = 0.5_dp*sys%stiffness*l0*strain**2
            slack = .false.
        case (CABLE_SLACK)
            slack = .true.
        case default
            if (strain > 0.0_dp) tension = max(0.0_dp, sys%stiffness*strain + &
                                                dashpot(sys, l0)*rate)
            slack = .not. (tension > 0.0_dp)
        end select
        f = -tension*u
    end subroutine cable

    !> Switching functions g = min(k eps, k eps + c d|s|/dtau) of BC and AD at state y (over
    !! m g): the law of CABLE_AUTO has the cable taut where g > 0 and slack where g <= 0.
    pure function cable_switch(sys, y) result(g)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp) :: g(2)
        real(dp) :: x(3, 2), v(3, 2), s0(3, 2), l0(2), u(3), length, strain, rate
        integer :: j
        call cable_points(sys, y, x, v, s0)
        l0 = natural_lengths(sys)
        do j = 1, 2
            length = norm2(x(:, j) - s0(:, j))
            u = (x(:, j) - s0(:, j))/length
            rate = dot_product(u, v(:, j))
            strain = (length - l0(j))/l0(j)
            g(j) = min(sys%stiffness*strain, sys%stiffness*strain + dashpot(sys, l0(j))*rate)
        end do
    end function cable_switch

    !> cable_switch from the cables' stretches |s_j| - L0_j and their rates (stretch(:, j)
    !! for cable j; elastic_gen, where they are states): g_j = min(k e, k e + c e') with
    !! e = stretch/L0.
    pure function cable_switch_stretched(sys, stretch) result(g)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: stretch(2, 2)   !! (stretch, rate) of BC, AD (b', b'/tau)
        real(dp) :: g(2)
        real(dp) :: l0(2)
        integer :: j
        l0 = natural_lengths(sys)
        do j = 1, 2
            g(j) = min(sys%stiffness*stretch(1, j)/l0(j), sys%stiffness*stretch(1, j)/l0(j) + &
                       dashpot(sys, l0(j))*stretch(2, j))
        end do
    end function cable_switch_stretched

    !> Body points C (j = 1) and D (j = 2) and their velocities in n components, and the
    !! supports B and A, at state y.
    pure subroutine cable_points(sys, y, x, v, s0)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: x(3, 2), v(3, 2), s0(3, 2)
        real(dp) :: r(3, 3), rb(3), rw(3), omega(3)
        integer :: j
        r = quat_to_matrix(y(7:10))
        omega = matmul(r, y(11:13))
        do j = 1, 2
            rb = body_c(sys%p)
            if (j == 2) rb(3) = rb(3) - 1.0_dp
            rw = matmul(r, rb)
            x(:, j) = y(1:3) + rw
            v(:, j) = y(4:6) + cross(omega, rw)
        end do
        s0(:, 1) = [0.0_dp, -sys%p%big_b, 0.0_dp]
        s0(:, 2) = 0.0_dp
    end subroutine cable_points

    !> Highest stretching frequency of the cables, omega_s = sqrt((k/L0) (1 + rho^2/I_min))
    !! (rho the larger distance of C, D from R*, I_min the smallest principal moment, L0 the
    !! shorter natural length), per unit tau; at least 1.
    pure real(dp) function stretch_frequency(sys) result(ws)
        type(elastic_t), intent(in) :: sys
        real(dp) :: rc(3), rho2
        rc = body_c(sys%p)
        rho2 = max(dot_product(rc, rc), dot_product(rc - [0.0_dp, 0.0_dp, 1.0_dp], &
                                                    rc - [0.0_dp, 0.0_dp, 1.0_dp]))
        ws = sqrt(sys%stiffness/minval(natural_lengths(sys))*(1.0_dp + rho2/minval(sys%p%inertia)))
        ws = max(1.0_dp, ws)
    end function stretch_frequency

    !> Absolute tolerances for the 13 states consistent with the energy norm of the stiff
    !! cable modes.  The error test allows a position error of about rtol |R*| + atol (the
    !! positions' scale |R*| ~ L, the longer natural length) and a quaternion error of about
    !! rtol + atol; a stretch error dx carries the energy of a velocity error omega_s dx
    !! (omega_s = stretch_frequency).  So the velocities get omega_s (atol + dx) and the
    !! angular velocities omega_s (atol + dx/L) as absolute tolerances, with
    !! dx = min(rtol L, L/(2k)): the position tolerance, but never more than the static
    !! stretch of a cable under half the weight, L/(2k), so that a stretch-rate error allowed
    !! by the test cannot by itself undo the stretch of a cable the motion keeps taut (at
    !! k = 1e8 and rtol 1e-6 the cables would otherwise chatter between taut and slack).
    !! With one atol for every state the BDF error test chases the harmless, decaying stiff
    !! oscillations that the positions' own tolerance excites in the velocities; with the
    !! velocities' atol omega_s atol alone, the k = 1e6 case of tests/bench_elastic.f90 took
    !! about twice the steps, with errors against a reference of the same size.
    !! The soft (pendulum) velocities stay controlled through the positions: their errors
    !! are the positions' times the pendulum frequencies, far below omega_s.
    !! rtol absent: 0 (velocities atol omega_s atol).
    pure function elastic_atol(sys, atol, rtol) result(a)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: atol            !! absolute tolerance of the positions
        real(dp), intent(in), optional :: rtol  !! the run's relative tolerance
        real(dp) :: a(ELASTIC_NSTATE)
        real(dp) :: ws, dx, ll
        ll = maxval(natural_lengths(sys))
        dx = 0.0_dp
        if (present(rtol)) dx = min(rtol*ll, 0.5_dp*ll/sys%stiffness)
        ws = stretch_frequency(sys)
        a = atol
        a(4:6) = ws*(atol + dx)
        a(11:13) = ws*(atol + dx/ll)
    end function elastic_atol

    !> Natural (unstretched) lengths of BC and AD over b'.
    pure function natural_lengths(sys) result(l0)
        type(elastic_t), intent(in) :: sys
        real(dp) :: l0(2)
        l0 = [sys%p%big_l, sys%p%big_lp]
        if (sys%l0(1) > 0.0_dp) l0(1) = sys%l0(1)
        if (sys%l0(2) > 0.0_dp) l0(2) = sys%l0(2)
    end function natural_lengths

    !> Derivative of the state and the cables' state; stretch: the cables' stretches and
    !! their rates as known (stretch(:, j) for cable j, see cable).
    pure subroutine dynamics(sys, y, ydot, cab, stretch)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(elastic_cables_t), intent(out) :: cab
        real(dp), intent(in), optional :: stretch(2, 2)
        real(dp) :: r(3, 3), x(3, 2), v(3, 2), f(3), force(3), torque(3)
        real(dp) :: ib(3, 3), ibinv(3, 3), wb(3), q(4), s0(3, 2), l0(2), en(2)
        integer :: j
        q = y(7:10)
        r = quat_to_matrix(q)
        wb = y(11:13)
        call cable_points(sys, y, x, v, s0)
        l0 = natural_lengths(sys)
        force = [0.0_dp, 0.0_dp, -1.0_dp]
        torque = 0.0_dp
        do j = 1, 2
            if (present(stretch)) then
                call cable(sys, sys%mode(j), s0(:, j), x(:, j), v(:, j), l0(j), f, &
                           cab%tension(j), cab%strain(j), cab%length(j), cab%length_rate(j), &
                           cab%slack(j), en(j), stretch(:, j))
            else
                call cable(sys, sys%mode(j), s0(:, j), x(:, j), v(:, j), l0(j), f, &
                           cab%tension(j), cab%strain(j), cab%length(j), cab%length_rate(j), &
                           cab%slack(j), en(j))
            end if
            force = force + f
            torque = torque + cross(x(:, j) - y(1:3), f)
        end do
        cab%spring_energy = sum(en)
        call body_inertia(sys%p, ib, ibinv)
        ydot(1:3) = y(4:6)
        ydot(4:6) = force
        ! qdot = (1/2) q (x) (0, omega_body) + a (1 - |q|^2) q
        ydot(7) = -0.5_dp*dot_product(q(2:4), wb)
        ydot(8:10) = 0.5_dp*(q(1)*wb + cross(q(2:4), wb))
        ydot(7:10) = ydot(7:10) + sys%quat_rate*(1.0_dp - dot_product(q, q))*q
        ydot(11:13) = matmul(ibinv, matmul(transpose(r), torque) - cross(wb, matmul(ib, wb)))
    end subroutine dynamics

    !> ERR_NUMERIC when the orientation quaternion of state y is zero (no rotation matrix).
    pure subroutine check_quaternion(y, stat)
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        type(status_t), intent(out) :: stat
        stat%code = STATUS_OK
        if (.not. (dot_product(y(7:10), y(7:10)) > 0.0_dp)) &
            call set_error(stat, ERR_NUMERIC, 'elastic model: zero orientation quaternion')
    end subroutine check_quaternion

    !> elastic_rhs with the cables' stretches |s_j| - L0_j and their rates given
    !! (stretch(:, j) for cable j): the tensions from these (elastic_gen, where they are
    !! states), the directions of the forces from the pose.
    subroutine elastic_rhs_stretched(sys, y, stretch, ydot, stat)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp), intent(in) :: stretch(2, 2)   !! (stretch, rate) of BC, AD (b', b'/tau)
        real(dp), intent(out) :: ydot(:)        !! the derivative of y
        type(status_t), intent(out) :: stat
        type(elastic_cables_t) :: cab
        ydot = 0.0_dp
        call check_quaternion(y, stat)
        if (stat%code /= STATUS_OK) return
        call dynamics(sys, y, ydot, cab, stretch)
    end subroutine elastic_rhs_stretched

    !> Right-hand side: Newton's and Euler's equations with the two spring-dashpot cables.
    subroutine elastic_rhs(sys, t, y, ydot, stat)
        class(elastic_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! tau (not used: the system is autonomous)
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp), intent(out) :: ydot(:)        !! its derivative
        type(status_t), intent(out) :: stat
        type(elastic_cables_t) :: cab
        call unused(t)
        ydot = 0.0_dp
        call check_quaternion(y, stat)
        if (stat%code /= STATUS_OK) return
        call dynamics(sys, y, ydot, cab)
    end subroutine elastic_rhs

    ! ------------------------------------------------------------------------------------
    ! Analytic Jacobian of the right-hand side
    ! ------------------------------------------------------------------------------------

    !> The matrix [a]x of the cross product: skew(a) b = a x b.
    pure function skew(a) result(m)
        real(dp), intent(in) :: a(3)
        real(dp) :: m(3, 3)
        m(:, 1) = [0.0_dp, a(3), -a(2)]
        m(:, 2) = [-a(3), 0.0_dp, a(1)]
        m(:, 3) = [a(2), -a(1), 0.0_dp]
    end function skew

    !> The turning of the body frame per change of q: a change dq of the quaternion turns
    !! R = quat_to_matrix(q) (built from q/|q|) through the small angle xis dq in n components,
    !! R xib dq in body components, with
    !!   xis = (2/|q|^2) [-q_v | w I + [q_v]x],   xib = (2/|q|^2) [-q_v | w I - [q_v]x]
    !! (columns w, x, y, z; dq along q turns nothing: R is homogeneous of degree 0 in q).
    !! Hence d(R v)/dq = -[R v]x xis = -R [v]x xib for a fixed v, d(R^T f)/dq = [R^T f]x xib.
    pure subroutine quat_turning(q, xis, xib)
        real(dp), intent(in) :: q(4)
        real(dp), intent(out) :: xis(3, 4), xib(3, 4)
        real(dp) :: s, qx(3, 3)
        integer :: i
        s = 2.0_dp/dot_product(q, q)
        qx = skew(q(2:4))
        xis(:, 1) = -s*q(2:4)
        xib(:, 1) = xis(:, 1)
        xis(:, 2:4) = s*qx
        xib(:, 2:4) = -s*qx
        do i = 1, 3
            xis(i, 1 + i) = xis(i, 1 + i) + s*q(1)
            xib(i, 1 + i) = xib(i, 1 + i) + s*q(1)
        end do
    end subroutine quat_turning

    !> Body point of cable j in ntilde components: C (j = 1) or D = C - ntilde3 (j = 2), as in
    !! cable_points.
    pure function body_point(p, j) result(rb)
        type(pendulum_t), intent(in) :: p
        integer, intent(in) :: j
        real(dp) :: rb(3)
        rb = body_c(p)
        if (j == 2) rb(3) = rb(3) - 1.0_dp
    end function body_point

    !> Derivatives of the force f = -T u of a taut cable (T = k eps + c rate, s = x - s0,
    !! u = s/|s|, rate = u . v) on its body point, in rank-one form:
    !!   df/dx = u h^T - t I,   df/dv = -c u u^T,   t = T/|s|,  h = t u - (k/L0) u - (c/|s|) P v
    !! (P = I - u u^T: du/dx = P/|s|, d|s|/dx = u^T, d rate/dx = (P v)^T/|s|, d rate/dv = u^T).
    pure subroutine cable_derivs(sys, s, v, l0, tension, u, h, t, c)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: s(3), v(3), l0, tension
        real(dp), intent(out) :: u(3), h(3), t, c
        real(dp) :: length
        length = norm2(s)
        u = s/length
        c = dashpot(sys, l0)
        t = tension/length
        h = (t - sys%stiffness/l0)*u - (c/length)*(v - dot_product(u, v)*u)
    end subroutine cable_derivs

    !> Jacobian of dynamics: jac(i, j) = d ydot_i / d y_j, the exact derivative of the law of
    !! each cable's mode (CABLE_AUTO: of the branch active at y, i.e. 0 for a slack cable).
    !! Cable j acts at x_j = R* + R rb_j moving with v_j = v* + R (omega x rb_j), R = R(q/|q|)
    !! (omega in body components); quat_turning gives d(R a)/dq = -R [a]x xib for body-fixed
    !! a, so dx_j/dq = -R [rb_j]x xib, dv_j/dq = -R [omega x rb_j]x xib, dv_j/domega =
    !! -R [rb_j]x.  With cable_derivs' df/dx = u h^T - t I, df/dv = -c u u^T:
    !!   df_j/dy = u rho^T - t dx_j/dy,  rho = (h, -c u, (c (R^T u) x (omega x rb_j) -
    !!             (R^T h) x rb_j)^T xib, c (R^T u) x rb_j)   (R*, v*, q, omega columns)
    !! in v*' (R*' = v* gives the identity block).  The torque in body components,
    !! tau_b = sum rb_j x R^T f_j, with R^T f_j = -T R^T u and d(R^T f)/dq = [R^T f]x xib:
    !!   dtau_b/dy = sum [rb_j]x (R^T u rho^T - t R^T dx_j/dy + [R^T f_j]x xib in the q columns)
    !!   = sum (rb_j x R^T u) rho^T - t [rb_j]x R^T (R* columns)
    !!     + [rb_j]x [t rb_j - T R^T u]x xib (q columns),
    !! and omega' = I^-1 (tau_b - omega x I omega), d(omega x I omega)/domega =
    !! [omega]x I - [I omega]x.  qdot = (1/2) q (x) (0, omega) + a (1 - |q|^2) q is linear in
    !! q and in omega, plus d/dq of the stabilisation a (1 - |q|^2) I - 2 a q q^T.
    !! The cable terms are rank one or 3 x 3 blocks: about three right-hand sides' work.
    pure subroutine dynamics_jacobian(sys, y, jac)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: jac(ELASTIC_NSTATE, ELASTIC_NSTATE)
        real(dp) :: q(4), wb(3), r(3, 3), x(3, 2), v(3, 2), s0(3, 2), l0(2), ib(3, 3)
        real(dp) :: ibinv(3, 3), xis(3, 4), xib(3, 4), ixib(3, 4), rho(ELASTIC_NSTATE)
        real(dp) :: rb(3), rw(3), f(3), u(3), h(3), ub(3), hb(3), z(3), mu(3), e(3)
        real(dp) :: m(3, 3), rbx(4)
        real(dp) :: tension, strain, length, rate, energy, t, c, rz, nq
        logical :: slack
        integer :: i, j, k
        q = y(7:10)
        wb = y(11:13)
        r = quat_to_matrix(q)
        call quat_turning(q, xis, xib)
        call cable_points(sys, y, x, v, s0)
        l0 = natural_lengths(sys)
        call body_inertia(sys%p, ib, ibinv)
        ixib = matmul(ibinv, xib)
        jac = 0.0_dp
        ! R*' = v*
        do i = 1, 3
            jac(i, 3 + i) = 1.0_dp
        end do
        ! the cables: forces in v*', torques about R* in omega'
        do j = 1, 2
            call cable(sys, sys%mode(j), s0(:, j), x(:, j), v(:, j), l0(j), f, tension, &
                       strain, length, rate, slack, energy)
            if (slack) cycle                    ! no force, and none nearby in this branch
            call cable_derivs(sys, x(:, j) - s0(:, j), v(:, j), l0(j), tension, u, h, t, c)
            rb = body_point(sys%p, j)
            rw = matmul(r, rb)
            ub = matmul(u, r)                   ! R^T u
            hb = matmul(h, r)                   ! R^T h
            rho(1:3) = h
            rho(4:6) = -c*u
            e = c*cross(ub, cross(wb, rb)) - cross(hb, rb)
            rho(7:10) = matmul(e, xib)
            rho(11:13) = c*cross(ub, rb)
            ! force: u rho^T - t dx_j/dy, dx_j/dR* = I, dx_j/dq = -[R rb_j]x xis
            do k = 1, ELASTIC_NSTATE
                jac(4:6, k) = jac(4:6, k) + rho(k)*u
            end do
            do i = 1, 3
                jac(3 + i, i) = jac(3 + i, i) - t
            end do
            do k = 1, 4
                jac(4:6, 6 + k) = jac(4:6, 6 + k) + t*cross(rw, xis(:, k))
            end do
            ! torque rb x R^T f_j, times I^-1: rank one, R* columns, q columns
            e = cross(rb, ub)
            mu = matmul(ibinv, e)
            do k = 1, ELASTIC_NSTATE
                jac(11:13, k) = jac(11:13, k) + rho(k)*mu
            end do
            do i = 1, 3                         ! [rb]x R^T e_i = rb x (row i of R)
                m(:, i) = cross(rb, r(i, :))
            end do
            jac(11:13, 1:3) = jac(11:13, 1:3) - t*matmul(ibinv, m)
            ! q columns: [rb]x [z]x xib = z (rb^T xib) - (rb . z) xib
            z = t*rb - tension*ub
            mu = matmul(ibinv, z)
            rbx = matmul(rb, xib)
            rz = dot_product(rb, z)
            do k = 1, 4
                jac(11:13, 6 + k) = jac(11:13, 6 + k) + rbx(k)*mu - rz*ixib(:, k)
            end do
        end do
        ! omega' = I^-1 (tau_b - omega x I omega)
        m = skew(wb)
        e = matmul(ib, wb)
        m = matmul(m, ib) - skew(e)
        jac(11:13, 11:13) = jac(11:13, 11:13) - matmul(ibinv, m)
        ! qdot: w' = -(1/2) q_v . omega, q_v' = (1/2) (q_w omega + q_v x omega)
        jac(7, 8:10) = -0.5_dp*wb
        jac(8:10, 7) = 0.5_dp*wb
        jac(8:10, 8:10) = -0.5_dp*skew(wb)
        jac(7, 11:13) = -0.5_dp*q(2:4)
        jac(8:10, 11:13) = 0.5_dp*skew(q(2:4))
        do i = 1, 3
            jac(7 + i, 10 + i) = jac(7 + i, 10 + i) + 0.5_dp*q(1)
        end do
        ! ... + a (1 - |q|^2) q
        nq = dot_product(q, q)
        do k = 1, 4
            jac(7:10, 6 + k) = jac(7:10, 6 + k) - 2.0_dp*sys%quat_rate*q(k)*q
            jac(6 + k, 6 + k) = jac(6 + k, 6 + k) + sys%quat_rate*(1.0_dp - nq)
        end do
    end subroutine dynamics_jacobian

    !> Analytic Jacobian of elastic_rhs, dfdy(i, j) = d ydot_i / d y_j (13 x 13), in the
    !! cables' current modes (dynamics_jacobian).  Costs about three right-hand sides.
    subroutine elastic_jacobian(sys, t, y, dfdy, stat)
        class(elastic_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! tau (not used: the system is autonomous)
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp), intent(out) :: dfdy(:, :)     !! d ydot_i / d y_j (13 x 13)
        type(status_t), intent(out) :: stat
        call unused(t)
        dfdy = 0.0_dp
        call check_quaternion(y, stat)
        if (stat%code /= STATUS_OK) return
        call dynamics_jacobian(sys, y, dfdy(1:ELASTIC_NSTATE, 1:ELASTIC_NSTATE))
    end subroutine elastic_jacobian

    !> The elastic model has an analytic Jacobian (elastic_jacobian).
    logical function elastic_has_jacobian(sys)
        class(elastic_t), intent(in) :: sys
        call unused(sys)
        elastic_has_jacobian = .true.
    end function elastic_has_jacobian

    ! ------------------------------------------------------------------------------------
    ! Conversions
    ! ------------------------------------------------------------------------------------

    !> Elastic state with the pose and velocities of a chart state of the inextensible model
    !! (bifilar_model): the cables at their natural lengths (unstretched, tension 0 before
    !! any damping), R* and the frame from eqs. (8), (21)-(22), the velocity of C from the
    !! cable's direction sigma and its rate, omega from eq. (14).  Regular at theta2 = 0.
    pure function elastic_from_chart(p, yc) result(y)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: yc(10)          !! chart state (theta1, sigma, theta4, theta5, rates)
        real(dp) :: y(ELASTIC_NSTATE)
        real(dp) :: th(5), thd(5), n(3, 3), e(3), zeta, c(3), vc(3), omega(3), rc(3)
        th = [yc(1), 0.0_dp, 0.0_dp, yc(4), yc(5)]
        thd = [yc(6), 0.0_dp, 0.0_dp, yc(9), yc(10)]
        n = direction_cosines(th)
        e = cable_direction(yc(2:3))
        zeta = -e(3)
        c = [0.0_dp, -p%big_b, 0.0_dp] + p%big_l*e
        vc = p%big_l*[yc(7), yc(8), dot_product(yc(2:3), yc(7:8))/zeta]
        omega = matmul(omega_coeffs(th), thd)
        rc = -p%r*(sin(p%lambda)*n(1, :) - cos(p%lambda)*n(3, :))   ! C - R*
        y(1:3) = c - rc
        y(4:6) = vc - cross(omega, rc)
        y(7:10) = matrix_to_quat(transpose(n))
        y(11:13) = matmul(n, omega)
    end function elastic_from_chart

    !> The start of an elastic run from a start of the inextensible model: the same pose and
    !! velocities (elastic_from_chart), and the natural lengths set to L0 = l/(1 + T0/k)
    !! with T0 the tension of the paper's model at that state (bifilar_model evaluate), so
    !! the cables carry exactly the paper's tensions at tau = 0.  A cable the paper's model
    !! finds slack (T0 <= 0) keeps L0 = l.  sys%p, sys%stiffness must be set.
    subroutine elastic_start(sys, yc, y0, stat)
        class(elastic_t), intent(inout) :: sys
        real(dp), intent(in) :: yc(10)          !! chart state of the inextensible model
        real(dp), intent(out) :: y0(ELASTIC_NSTATE)  !! elastic state at the start
        type(status_t), intent(out) :: stat     !! ERR_MODEL/ERR_NUMERIC from evaluate
        type(motion_t) :: mo
        real(dp) :: th(5), thd(5), t0(2)
        y0 = elastic_from_chart(sys%p, yc)
        call paper_angles(yc, 0.0_dp, th, thd)
        call evaluate(sys%p, yc, th(3), mo, stat)
        if (stat%code /= 0) return
        t0 = max(0.0_dp, [mo%t_bc, mo%t_ad])
        sys%l0 = [sys%p%big_l, sys%p%big_lp]/(1.0_dp + t0/sys%stiffness)
    end subroutine elastic_start

    !> Elastic state from the paper's angles and rates (same pose and velocities).
    pure function elastic_from_angles(p, th, thd) result(y)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: th(5), thd(5)   !! theta_1..5 (rad) and rates
        real(dp) :: y(ELASTIC_NSTATE)
        y = elastic_from_chart(p, chart_state(th, thd))
    end function elastic_from_angles

    !> The chart-like vector (theta1, sigma1, sigma2, theta4, theta5 and their rates) of an
    !! elastic state, from its pose: theta4, theta5 from D - C = -ntilde3 =
    !! (c5 s4, c5 c4, s5); theta1 from the rotation about CD, ntilde1 = s1 u + c1 w with
    !! u = (c4, -s4, 0), w = (s4 s5, c4 s5, -c5); sigma the horizontal components of the
    !! unit vector (C - B)/|C - B|; theta1, theta4 continued to the nearest 2 pi multiple of
    !! th_ref(1), th_ref(4) when given, else in (-pi, pi].  Rates: d' = omega x d,
    !! theta1' = omega . ntilde3 - s5 theta4' (eq. (14)).
    pure function elastic_chart(p, y, th_ref) result(yc)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp), intent(in), optional :: th_ref(5)  !! previous angles (continuity)
        real(dp) :: yc(10)
        real(dp) :: c(3), d(3), e(3), vc(3), vd(3), n(3, 3), omega(3), dd(3), ddot(3)
        real(dp) :: s4, c4, s5, c5, th1, th4, th5, u(3), w(3), sbc(3), len, edot(3)
        call elastic_pose(p, y, c, d, e, vc, vd, n, omega)
        dd = -n(3, :)
        th5 = asin(max(-1.0_dp, min(1.0_dp, dd(3))))
        th4 = atan2(dd(1), dd(2))
        s4 = sin(th4); c4 = cos(th4); s5 = sin(th5); c5 = cos(th5)
        u = [c4, -s4, 0.0_dp]
        w = [s4*s5, c4*s5, -c5]
        th1 = atan2(dot_product(n(1, :), u), dot_product(n(1, :), w))
        if (present(th_ref)) then
            th1 = th1 + 2.0_dp*pi*anint((th_ref(1) - th1)/(2.0_dp*pi))
            th4 = th4 + 2.0_dp*pi*anint((th_ref(4) - th4)/(2.0_dp*pi))
        end if
        ddot = cross(omega, dd)
        sbc = c - [0.0_dp, -p%big_b, 0.0_dp]
        len = norm2(sbc)
        edot = (vc - dot_product(vc, sbc/len)*sbc/len)/len
        yc(1:5) = [th1, sbc(1)/len, sbc(2)/len, th4, th5]
        yc(10) = ddot(3)/c5
        yc(9) = (c4*ddot(1) - s4*ddot(2))/c5
        yc(6) = dot_product(omega, n(3, :)) - s5*yc(9)
        yc(7:8) = edot(1:2)
    end function elastic_chart

    !> Total energy over m g b': kinetic + gravity (height of R*) + the springs'.
    pure real(dp) function elastic_energy(sys, y) result(en)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp) :: ydot(ELASTIC_NSTATE), ib(3, 3), ibinv(3, 3)
        type(elastic_cables_t) :: cab
        call dynamics(sys, y, ydot, cab)
        call body_inertia(sys%p, ib, ibinv)
        en = 0.5_dp*dot_product(y(4:6), y(4:6)) + 0.5_dp*dot_product(y(11:13), &
             matmul(ib, y(11:13))) + y(3) + cab%spring_energy
    end function elastic_energy

    !> Everything reported about the motion at one instant, in the same terms as the
    !! inextensible model's evaluate (so the same output rows): theta1..5 and rates from the
    !! pose (elastic_chart, then paper_angles for theta2, theta3 with the branch nearest
    !! th3_ref), R*, v, a, omega, alpha (n components), Q and Q_axis, T_BC and T_AD from the
    !! springs (0 when slack), energy including the springs', residual = |AD| - l' over b'
    !! (the stretch of AD).  mo%qdd is not defined for this model and is left 0.
    subroutine elastic_evaluate(sys, y, th3_ref, mo, stat, th_ref, cab)
        class(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp), intent(in) :: th3_ref         !! previous theta_3 (branch choice)
        type(motion_t), intent(out) :: mo
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: th_ref(5)  !! previous angles: theta1, theta4 continuity
        type(elastic_cables_t), intent(out), optional :: cab
        real(dp) :: ydot(ELASTIC_NSTATE), yc(10), c(3), d(3), pe(3), vc(3), vd(3), n(3, 3)
        real(dp) :: omega(3), mid(3), r(3, 3)
        type(elastic_cables_t) :: cb
        call check_quaternion(y, stat)
        if (stat%code /= STATUS_OK) return
        call dynamics(sys, y, ydot, cb)
        if (present(th_ref)) then
            yc = elastic_chart(sys%p, y, th_ref)
        else
            yc = elastic_chart(sys%p, y)
        end if
        call paper_angles(yc, th3_ref, mo%th, mo%thd)
        call elastic_pose(sys%p, y, c, d, pe, vc, vd, n, omega)
        r = quat_to_matrix(y(7:10))
        mo%qdd = 0.0_dp
        mo%rstar = y(1:3)
        mo%vstar = y(4:6)
        mo%astar = ydot(4:6)
        mo%omega = omega
        mo%alpha = matmul(r, ydot(11:13))
        mo%frame = body_axes(sys%p, n)
        mo%t_bc = cb%tension(CABLE_BC)
        mo%t_ad = cb%tension(CABLE_AD)
        mo%energy = elastic_energy(sys, y)
        mo%residual = norm2(d) - sys%p%big_lp
        mid = c - 0.5_dp*n(3, :)
        mo%q_sway = sqrt(pe(1)**2 + (pe(2) + 0.5_dp*sys%p%big_b)**2)
        mo%q_axis = sqrt((pe(1) - mid(1))**2 + (pe(2) - mid(2))**2)
        if (present(cab)) cab = cb
    end subroutine elastic_evaluate

end module elastic_model
