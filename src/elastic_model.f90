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
!! Slack is a state of this model, not an error: tensions, strains and slack flags are
!! reported (elastic_cables_t) so the caller can time the slack intervals.
!!
!! The body: m R*'' = -m g n3 + F_BC + F_AD;  Euler's equations in ntilde components,
!! I omega' + omega x I omega = sum (r_P x F_P), I = btilde^T diag(I_i) btilde.
module elastic_model
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_NUMERIC, STATUS_OK
    use ode_system, only: ode_system_t
    use geometry, only: pendulum_t, direction_cosines, cable_direction, body_axes
    use kinematics, only: omega_coeffs
    use gen_forces, only: inertia_dyadic
    use bifilar_model, only: motion_t, chart_state, paper_angles, evaluate
    implicit none
    private

    integer, parameter, public :: ELASTIC_NSTATE = 13  !! y = (R*, v*, q, omega_body)
    integer, parameter, public :: CABLE_BC = 1, CABLE_AD = 2

    !> The elastic pendulum as an ODE system for the integrator.
    type, extends(ode_system_t), public :: elastic_t
        type(pendulum_t) :: p                   !! scaled parameters (stab_rate is not used)
        real(dp) :: stiffness = 1.0e6_dp        !! k = EA/(m g) of each cable (nondimensional)
        real(dp) :: damping = 0.0_dp            !! zeta: damping ratio of each cable (see above)
        real(dp) :: quat_rate = 1.0_dp          !! a: rate of the quaternion-norm stabilisation
        real(dp) :: l0(2) = -1.0_dp             !! natural lengths of BC, AD over b'; <= 0: the
                                                !! deck's l/b', l'/b' (see elastic_start)
    contains
        procedure :: rhs => elastic_rhs
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
    public :: natural_lengths, elastic_atol

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

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
    end function cross

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

    !> One cable: support point s0, body point x with velocity v, natural length l0.
    !! Force on the body point and the cable's state.
    pure subroutine cable(sys, s0, x, v, l0, f, tension, strain, length, rate, slack, energy)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: s0(3), x(3), v(3), l0
        real(dp), intent(out) :: f(3), tension, strain, length, rate, energy
        logical, intent(out) :: slack
        real(dp) :: s(3), u(3), cdash
        s = x - s0
        length = norm2(s)
        u = s/length
        rate = dot_product(u, v)
        strain = (length - l0)/l0
        tension = 0.0_dp
        energy = 0.0_dp
        if (strain > 0.0_dp) then
            cdash = 2.0_dp*sys%damping*sqrt(sys%stiffness/l0)
            tension = max(0.0_dp, sys%stiffness*strain + cdash*rate)
            energy = 0.5_dp*sys%stiffness*l0*strain**2
        end if
        slack = .not. (tension > 0.0_dp)
        f = -tension*u
    end subroutine cable

    !> Absolute tolerances for the 13 states consistent with the energy norm of the stiff
    !! cable modes: atol for the positions and the quaternion, atol * omega_s for the
    !! velocities and angular velocities, omega_s = sqrt((k/L0) (1 + rho^2/I_min)) the highest
    !! stretching frequency (rho the larger distance of C, D from R*, I_min the smallest
    !! principal moment).  A stretch error dx and a velocity error omega_s dx carry the same
    !! energy.  With one atol for every state the BDF error test would chase the harmless,
    !! decaying stiff transients that the positions' own tolerance excites in the
    !! velocities (velocity errors ~ omega_s times the position errors), and the steps
    !! would grow like sqrt(k).
    pure function elastic_atol(sys, atol) result(a)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: atol            !! absolute tolerance of the positions
        real(dp) :: a(ELASTIC_NSTATE)
        real(dp) :: rc(3), rho2, ws
        rc = body_c(sys%p)
        rho2 = max(dot_product(rc, rc), dot_product(rc - [0.0_dp, 0.0_dp, 1.0_dp], &
                                                    rc - [0.0_dp, 0.0_dp, 1.0_dp]))
        ws = sqrt(sys%stiffness/minval(natural_lengths(sys))*(1.0_dp + rho2/minval(sys%p%inertia)))
        ws = max(1.0_dp, ws)
        a = atol
        a(4:6) = atol*ws
        a(11:13) = atol*ws
    end function elastic_atol

    !> Natural (unstretched) lengths of BC and AD over b'.
    pure function natural_lengths(sys) result(l0)
        type(elastic_t), intent(in) :: sys
        real(dp) :: l0(2)
        l0 = [sys%p%big_l, sys%p%big_lp]
        if (sys%l0(1) > 0.0_dp) l0(1) = sys%l0(1)
        if (sys%l0(2) > 0.0_dp) l0(2) = sys%l0(2)
    end function natural_lengths

    !> Derivative of the state and the cables' state.
    pure subroutine dynamics(sys, y, ydot, cab)
        type(elastic_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: ydot(:)
        type(elastic_cables_t), intent(out) :: cab
        real(dp) :: r(3, 3), rb(3, 2), rw(3), x(3), v(3), omega(3), f(3), force(3), torque(3)
        real(dp) :: ib(3, 3), ibinv(3, 3), wb(3), q(4), s0(3, 2), l0(2), en(2)
        integer :: j
        q = y(7:10)
        r = quat_to_matrix(q)
        wb = y(11:13)
        omega = matmul(r, wb)
        rb(:, 1) = body_c(sys%p)
        rb(:, 2) = rb(:, 1) - [0.0_dp, 0.0_dp, 1.0_dp]
        s0(:, 1) = [0.0_dp, -sys%p%big_b, 0.0_dp]
        s0(:, 2) = 0.0_dp
        l0 = natural_lengths(sys)
        force = [0.0_dp, 0.0_dp, -1.0_dp]
        torque = 0.0_dp
        do j = 1, 2
            rw = matmul(r, rb(:, j))
            x = y(1:3) + rw
            v = y(4:6) + cross(omega, rw)
            call cable(sys, s0(:, j), x, v, l0(j), f, cab%tension(j), cab%strain(j), &
                       cab%length(j), cab%length_rate(j), cab%slack(j), en(j))
            force = force + f
            torque = torque + cross(rw, f)
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

    !> Right-hand side: Newton's and Euler's equations with the two spring-dashpot cables.
    subroutine elastic_rhs(sys, t, y, ydot, stat)
        class(elastic_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! tau (not used: the system is autonomous)
        real(dp), intent(in) :: y(:)            !! elastic state (13)
        real(dp), intent(out) :: ydot(:)        !! its derivative
        type(status_t), intent(out) :: stat
        type(elastic_cables_t) :: cab
        if (.false.) ydot(1) = t
        stat%code = STATUS_OK
        if (.not. (dot_product(y(7:10), y(7:10)) > 0.0_dp)) then
            ydot = 0.0_dp
            call set_error(stat, ERR_NUMERIC, 'elastic model: zero orientation quaternion')
            return
        end if
        call dynamics(sys, y, ydot, cab)
    end subroutine elastic_rhs

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
        stat%code = STATUS_OK
        if (.not. (dot_product(y(7:10), y(7:10)) > 0.0_dp)) then
            call set_error(stat, ERR_NUMERIC, 'elastic model: zero orientation quaternion')
            return
        end if
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
