!> The equations of motion of the bifilar pendulum, Kane & Tseng (1966) eqs. (37)-(43).
!!
!! Two forms of the same equations are assembled here, both as P qddot = Q (eq. (38)):
!!
!! * paper_accelerations: the paper's coordinates theta_1..theta_5, theta_5 eliminated with
!!   gamma_r = beta_r/beta_5 (eqs. (5)-(6), (31)), the fifth row the twice-differentiated
!!   constraint.  Singular where the paper's coordinates are: theta_2 = 0 (the coefficient of
!!   thddot_3 vanishes), cos(theta_5) = 0, beta_5 = 0.
!! * the integrated form (type bifilar_t): the cable BC's direction is described by its
!!   horizontal components sigma = s2 (c3, s3) instead of (theta_2, theta_3), a chart that is
!!   regular at theta_2 = 0 where the paper's is singular (pure torsion passes through it
!!   twice a period), and the dependent speed is the one with the largest constraint
!!   coefficient, so beta_5 = 0 is harmless.  Everything else (eqs. (8), (14), (19), (24),
!!   (27), (32)-(36)) is the paper's; the body's part of eqs. (24), (27) in its rigid-body
!!   form (module kinematics).  The state is
!!   y = (theta1, sigma1, sigma2, theta4, theta5, and their rates), eqs. (40)-(43).
!! Results are reported in the paper's theta_1..theta_5 (paper_angles).
!!
!! Eq. (38) is solved in the four independent accelerations (the constraint eliminated by
!! eq. (31)): their 4 x 4 generalized inertia, symmetric positive definite, is factored by
!! a written-out Cholesky (chol4, chol4_solve: lapack_wrap's la_small_chol at n = 4).  The
!! Jacobian Z of the chart right-hand side (eq. (51)) is exact: the derivatives of the
!! kinematics (chart_kinematics_tangent) carried through Kane's equations and the constraint
!! (eom_tangent), solved with the same factors (chart_jacobian); its ten columns in one
!! pass (jacobian_columns); the damping torque's derivative is in it.  The gradients of the
!! constraint, its rate and the energy are exact the same way (chart_invariant_gradients).
!! The damping torque about the vertical (&damping, pendulum_t c_v,
!! c_q) enters eq. (38) as an active torque through the partial angular velocities
!! (damping_torque).
!!
!! Forward sensitivities (ode_system's sens_point, sens_jv; the integrators' staggered
!! direct method): bifilar_t's `dirs` name the parameter direction of each sensitivity
!! (sens_dir_t).  Their df/dp is analytic: the change of the generalized active and inertia
!! forces with the moments and the damping, and of the kinematics at a fixed state with
!! the geometry (L, L', B, r, lambda), through Kane's equations and the constraint
!! (param_tangent), solved with the factor of eq. (38); the products J v are the tangents
!! of the kinematics through Kane's equations (eom_tangent), one per column, or the whole
!! of Z once a point needs more columns.
module bifilar_model
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_MODEL, ERR_NUMERIC
    use ode_system, only: ode_system_t
    use geometry, only: pendulum_t, pose_t, pose_of, body_pose, frame, body_axes, &
                        cable_direction, mass_centre, point_e
    use kinematics, only: omega_partials, omega_conv, v_partials, vdot_partials, &
                          omega_partials_tangent, omega_conv_tangent
    use vectors, only: cross
    use gen_forces, only: generalized_inertia, inertia_torque, project
    use unused_arg, only: unused
    implicit none
    private

    integer, parameter, public :: NSTATE = 10   !! y = (q(5), qdot(5))

    !> A direction in the pendulum's scaled parameters, dp/dx for the quantity x a
    !! sensitivity follows (pendulum_t's fields of the same names); its df/dp is analytic
    !! (param_tangent).  All 0: a sensitivity of the initial conditions only.
    type, public :: sens_dir_t
        real(dp) :: inertia(3) = 0.0_dp         !! d I_i/(m b'^2) / dx
        real(dp) :: c_v = 0.0_dp, c_q = 0.0_dp  !! of the damping
        real(dp) :: big_l = 0.0_dp, big_lp = 0.0_dp, big_b = 0.0_dp, r = 0.0_dp, &
                    lambda = 0.0_dp             !! of the geometry
    end type sens_dir_t


    !> Everything about the motion at one instant (scaled units: b' = m = g = 1).
    type, public :: motion_t
        real(dp) :: th(5) = 0.0_dp              !! theta_1..theta_5 (rad), paper's terms
        real(dp) :: thd(5) = 0.0_dp             !! their rates (rad per unit tau)
        real(dp) :: qdd(5) = 0.0_dp             !! chart accelerations
        real(dp) :: rstar(3) = 0.0_dp, vstar(3) = 0.0_dp, astar(3) = 0.0_dp  !! R*, v, a
        real(dp) :: omega(3) = 0.0_dp, alpha(3) = 0.0_dp  !! angular velocity, acceleration
        real(dp) :: frame(3, 3) = 0.0_dp        !! b_ij of eq. (11)
        real(dp) :: t_bc = 0.0_dp, t_ad = 0.0_dp  !! cable tensions over m g
        real(dp) :: energy = 0.0_dp             !! kinetic + potential energy over m g b'
        real(dp) :: residual = 0.0_dp           !! |AD| - l', over b'
        real(dp) :: q_sway = 0.0_dp             !! Q: horizontal distance of E from the vertical through O
        real(dp) :: q_axis = 0.0_dp             !! horizontal distance of E from the midpoint of CD
    end type motion_t

    !> What evaluate computes besides the angles and rates (the columns a run writes):
    !! the accelerations (and with them T_BC, T_AD, a of R*, alpha), the energy, the
    !! constraint residual, the side-sway Q and Q_axis.
    type, public :: motion_parts_t
        logical :: accelerations = .true.
        logical :: energy = .true.
        logical :: residual = .true.
        logical :: sway = .true.
    end type motion_parts_t

    !> Positions, partial velocities and convective accelerations at one chart state.
    type :: chart_kin_t
        type(pose_t) :: ps                      !! the pose's trigonometry
        real(dp) :: n(3, 3), c(3), d(3)         !! direction cosines (8), points C and D
        real(dp) :: e(3), zeta, econv(3)        !! cable direction B->C, -e(3), e'' at sigma'' = 0
        real(dp) :: rho(3)                      !! R* - C, eqs. (21)-(22)
        real(dp) :: jv(3, 5), cv(3)             !! R*: partial velocities, acceleration at qdd = 0
        real(dp) :: jw(3, 5), cw(3), omega(3)   !! the same for the rotation; angular velocity
        real(dp) :: jd(3, 5), cd(3)             !! the same for D
        real(dp) :: b(3, 3)                     !! principal axes b_i in n_j, eq. (11)
        real(dp) :: wb(3, 5), omb(3), cwb(3)    !! jw, omega, cw resolved in b_i
    end type chart_kin_t

    !> Eq. (38) assembled and factored at one state, and its solution.  The constraint row
    !! gives the dependent acceleration k from the four independent ones; Kane's rows for the
    !! independent speeds (partial velocities Jv(:,r) + gamma_r Jv(:,k), eq. (31)) are then
    !! a symmetric positive definite 4 x 4 system, held as its Cholesky factor.  (mk is set
    !! only for the Jacobian, by chart_jacobian.)
    type :: eom_t
        integer :: k                            !! the dependent coordinate (largest |gradg|)
        integer :: ind(4)                       !! the independent coordinates, ascending
        real(dp) :: gam(5)                      !! gamma_r = -gradg(r)/gradg(k), 0 at r = k
        real(dp) :: mk(5)                       !! column k of the generalized inertia M
        real(dp) :: chol(4, 4)                  !! Cholesky factor of T^T M T (T: eq. (31))
        real(dp) :: gradg(5), vd(3)             !! constraint gradient; velocity of D
        real(dp) :: qdd(5)                      !! the accelerations
    end type eom_t

    !> The pendulum as an ODE system for the integrator.
    type, extends(ode_system_t), public :: bifilar_t
        type(pendulum_t) :: p                   !! scaled parameters
        !> .true.: each right-hand side also keeps the state it evaluated and the cable
        !! tensions there (last_evaluation), for the validity check at the end of each step
        logical :: keep_tensions = .false.
        !> sin and cos of p%lambda, computed when p%lambda is first seen (lambda_key)
        real(dp), private :: lambda_key = huge(1.0_dp), sc_lambda(2) = 0.0_dp
        logical, private :: have_last = .false.
        !> the state of the last right-hand side, D and R*'s acceleration there (the cable
        !! tensions follow from them when asked, last_evaluation)
        real(dp), private :: last_y(NSTATE) = 0.0_dp, last_d(3) = 0.0_dp, last_a(3) = 0.0_dp
        !> the parameter direction of each sensitivity (sens_point; a column beyond them
        !! follows the initial conditions only)
        type(sens_dir_t), allocatable :: dirs(:)
        !> the point of the last sens_point, for sens_jv: the state, its kinematics, eq.
        !! (38) solved, R*'s acceleration, the torque on the body, the constraint's
        !! multiplier; Z once computed there; the columns taken by tangents there
        real(dp), private :: sp_y(NSTATE) = 0.0_dp
        type(chart_kin_t), private :: sp_k
        type(eom_t), private :: sp_eo
        real(dp), private :: sp_a(3) = 0.0_dp, sp_tq(3) = 0.0_dp, sp_mu = 0.0_dp
        real(dp), private :: sp_z(NSTATE, NSTATE) = 0.0_dp
        logical, private :: sp_have_z = .false.
        integer, private :: sp_cols = 0
    contains
        procedure :: rhs => bifilar_rhs
        procedure :: last_evaluation
        procedure :: sens_point => bifilar_sens_point
        procedure :: sens_jv => bifilar_sens_jv
        procedure :: sens_jacobian => bifilar_sens_jacobian
    end type bifilar_t

    public :: chart_state, paper_angles, chart_accelerations, paper_accelerations, evaluate
    public :: chart_positions, chart_energy, chart_constraint, chart_jacobian, step_tensions
    public :: chart_invariant_gradients
    public :: vertical_rate, vertical_rate_gradient

    !> The whole of Z (jacobian_columns' one pass, about 5 600 instructions) costs about 2.7
    !! tangents (2 100 each for one general direction through chart_kinematics_tangent and
    !! eom_tangent): sens_jv takes Z once the columns asked at a point exceed Z_COST.
    integer, parameter :: Z_COST = 2

contains

    !> Right-hand side of eqs. (42)-(43) in the regular chart.
    subroutine bifilar_rhs(sys, t, y, ydot, stat)
        class(bifilar_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! tau (not used: the system is autonomous)
        real(dp), intent(in) :: y(:)            !! chart state (10)
        real(dp), intent(out) :: ydot(:)        !! its derivative
        type(status_t), intent(out) :: stat
        type(chart_kin_t) :: k
        type(eom_t) :: eo
        call unused(t)
        call refresh_lambda(sys)
        call chart_solve(sys%p, y, k, eo, stat, sys%sc_lambda)
        ydot(1:5) = y(6:10)
        ydot(6:10) = eo%qdd
        if (sys%keep_tensions) then
            sys%have_last = stat%code == 0
            if (sys%have_last) then
                sys%last_y = y(1:NSTATE)
                sys%last_d = k%d
                sys%last_a = matmul(k%jv, eo%qdd) + k%cv
            end if
        end if
    end subroutine bifilar_rhs

    !> The state of the last right-hand side and the cable tensions there (over m g), when
    !! sys%keep_tensions is set; found = .false. when none was kept (or it failed).
    subroutine last_evaluation(sys, y, t_bc, t_ad, found)
        class(bifilar_t), intent(in) :: sys
        real(dp), intent(out) :: y(NSTATE)      !! chart state evaluated last
        real(dp), intent(out) :: t_bc, t_ad     !! the tensions there
        logical, intent(out) :: found
        found = sys%have_last
        y = sys%last_y
        t_bc = 0.0_dp
        t_ad = 0.0_dp
        if (found) call cable_tensions(sys%last_y, sys%last_d, sys%last_a, t_bc, t_ad)
    end subroutine last_evaluation

    !> sin and cos of sys%p%lambda, computed again only when lambda changed.
    pure subroutine refresh_lambda(sys)
        class(bifilar_t), intent(inout) :: sys
        if (sys%p%lambda /= sys%lambda_key) then
            sys%sc_lambda = [sin(sys%p%lambda), cos(sys%p%lambda)]
            sys%lambda_key = sys%p%lambda
        end if
    end subroutine refresh_lambda

    !> The kinematics at a chart state: the pose, C, D, the direction cosines, the cable
    !! direction e and the partial velocities / convective accelerations of R*, D and the
    !! rotation (eqs. (8), (14), (19), (24), (27) with theta_2 = theta_3 = 0 in the body's
    !! terms; the cable's columns from e(sigma)), the rotation also along the principal axes.
    pure subroutine chart_kinematics(p, y, k, sc_lambda, dynamics)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(:)
        type(chart_kin_t), intent(out) :: k
        real(dp), intent(in), optional :: sc_lambda(2)  !! sin, cos of p%lambda (body_pose)
        logical, intent(in), optional :: dynamics       !! .false.: only the pose, C, D, e and
                                                        !! R*'s motion (what the tensions need);
                                                        !! default .true.: everything
        real(dp) :: sdsd, ssd, iz
        associate (s4 => k%ps%s4, c4 => k%ps%c4, s5 => k%ps%s5, c5 => k%ps%c5, &
                   d4 => y(9), d5 => y(10))
            k%ps = body_pose(y(1), y(4), y(5), p%lambda, sc_lambda)
            call frame(k%ps, k%n)
            k%e = cable_direction(y(2:3))
            k%zeta = -k%e(3)
            k%c = [p%big_l*k%e(1), -p%big_b + p%big_l*k%e(2), p%big_l*k%e(3)]
            ! the cable: e(sigma) and its second derivative at sigma'' = 0
            sdsd = y(7)*y(7) + y(8)*y(8)
            ssd = y(2)*y(7) + y(3)*y(8)
            iz = 1.0_dp/k%zeta
            k%econv = [0.0_dp, 0.0_dp, (sdsd + (ssd*iz)**2)*iz]
            call omega_partials(k%ps, k%jw)
            k%omega = (k%jw(:, 1)*y(6) + k%jw(:, 4)*y(9)) + k%jw(:, 5)*y(10)
            call omega_conv(k%ps, y(6:10), k%cw)     ! reads the rates of theta_1, 4, 5
            ! R* = C + rho, eqs. (21)-(22); eqs. (24), (27): the cable's columns from e(sigma),
            ! the body's in their rigid-body form (Omega_j x rho; A x rho + omega x (omega x rho))
            k%rho = (p%r*k%ps%s_lambda)*k%n(1, :) - (p%r*k%ps%c_lambda)*k%n(3, :)
            k%jv(:, 1) = cross(k%jw(:, 1), k%rho)
            k%jv(:, 2) = [p%big_l, 0.0_dp, p%big_l*y(2)*iz]
            k%jv(:, 3) = [0.0_dp, p%big_l, p%big_l*y(3)*iz]
            k%jv(:, 4) = [k%rho(2), -k%rho(1), 0.0_dp]         ! -n3 x rho
            k%jv(:, 5) = cross(k%jw(:, 5), k%rho)
            k%cv = p%big_l*k%econv + cross(k%cw, k%rho) + cross(k%omega, cross(k%omega, k%rho))
            ! D = C + (c5 s4, c5 c4, s5), eq. (1)
            k%d = k%c + [c5*s4, c5*c4, s5]
            if (present(dynamics)) then
                if (.not. dynamics) return
            end if
            k%jd(:, 1) = 0.0_dp
            k%jd(:, 2:3) = k%jv(:, 2:3)
            k%jd(:, 4) = [c5*c4, -c5*s4, 0.0_dp]
            k%jd(:, 5) = [-s5*s4, -s5*c4, c5]
            k%cd = p%big_l*k%econv + [-c5*s4*(d4**2 + d5**2) - 2.0_dp*s5*c4*d4*d5, &
                                      -c5*c4*(d4**2 + d5**2) + 2.0_dp*s5*s4*d4*d5, -s5*d5**2]
            ! the rotation along the principal axes: b = btilde n; Omega_1 = ntilde_3, so
            ! b . Omega_1 = btilde(:,3); Omega_4 = -n_3; Omega_5 = c4 n_1 - s4 n_2
            k%b = body_axes(p, k%n)
            k%wb(:, 1) = p%btilde(:, 3)
            k%wb(:, 2:3) = 0.0_dp
            k%wb(:, 4) = -k%b(:, 3)
            k%wb(:, 5) = c4*k%b(:, 1) - s4*k%b(:, 2)
            k%omb = (k%wb(:, 1)*y(6) + k%wb(:, 4)*y(9)) + k%wb(:, 5)*y(10)
            k%cwb = k%b(:, 1)*k%cw(1) + k%b(:, 2)*k%cw(2) + k%b(:, 3)*k%cw(3)
        end associate
    end subroutine chart_kinematics

    !> The derivative of chart_kinematics along a change dy of the chart state: dk holds the
    !! change of every field of k (not dk%ps).  The body's motion is differentiated in its
    !! rigid-body form: a body vector u turns as du = dTheta x u with dTheta = Omega dtheta
    !! (eq. (14)); a body point at u from C has the partial velocities Omega_j x u and the
    !! convective acceleration A x u + omega x (omega x u) (eqs. (24), (27)).
    pure subroutine chart_kinematics_tangent(p, y, k, dy, dk)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(:)            !! chart state
        type(chart_kin_t), intent(in) :: k      !! its kinematics
        real(dp), intent(in) :: dy(:)           !! change of the state
        type(chart_kin_t), intent(out) :: dk
        real(dp) :: thd(5), dth(5), dthd(5), dtheta(3), u(3), du(3), sdsd, ssd, dsdsd, dssd
        real(dp) :: z, dz, z3
        integer :: i
        logical :: moved
        thd = [y(6), 0.0_dp, 0.0_dp, y(9), y(10)]
        dth = [dy(1), 0.0_dp, 0.0_dp, dy(4), dy(5)]
        dthd = [dy(6), 0.0_dp, 0.0_dp, dy(9), dy(10)]
        moved = any(dy(1:5) /= 0.0_dp)
        ! the cable
        z = k%zeta
        dz = -(y(2)*dy(2) + y(3)*dy(3))/z
        dk%zeta = dz
        dk%e = [dy(2), dy(3), -dz]
        dk%c = p%big_l*dk%e
        sdsd = y(7)*y(7) + y(8)*y(8)
        ssd = y(2)*y(7) + y(3)*y(8)
        dsdsd = 2.0_dp*(y(7)*dy(7) + y(8)*dy(8))
        dssd = dy(2)*y(7) + dy(3)*y(8) + y(2)*dy(7) + y(3)*dy(8)
        z3 = z**3
        dk%econv = [0.0_dp, 0.0_dp, dsdsd/z - sdsd*dz/z**2 + 2.0_dp*ssd*dssd/z3 &
                    - 3.0_dp*ssd**2*dz/(z3*z)]
        dk%jv(:, 2) = p%big_l*[0.0_dp, 0.0_dp, dy(2)/z - y(2)*dz/z**2]
        dk%jv(:, 3) = p%big_l*[0.0_dp, 0.0_dp, dy(3)/z - y(3)*dz/z**2]
        if (all(dy([1, 4, 5, 6, 9, 10]) == 0.0_dp)) then
            ! only the cable BC changes (four of Z's ten columns): the body's angles and
            ! rates, its frame, rotation and the offsets rho and D - C stay as they are
            dk%n = 0.0_dp
            dk%jw = 0.0_dp
            dk%omega = 0.0_dp
            dk%cw = 0.0_dp
            dk%rho = 0.0_dp
            dk%jv(:, 1) = 0.0_dp
            dk%jv(:, 4:5) = 0.0_dp
            dk%cv = p%big_l*dk%econv
            dk%d = dk%c
            dk%jd(:, 1) = 0.0_dp
            dk%jd(:, 2:3) = dk%jv(:, 2:3)
            dk%jd(:, 4:5) = 0.0_dp
            dk%cd = p%big_l*dk%econv
            dk%b = 0.0_dp
            dk%wb = 0.0_dp
            dk%omb = 0.0_dp
            dk%cwb = 0.0_dp
            dk%ps = pose_t()
            return
        end if
        ! the body's rotation: dTheta, the frame, the partial angular velocities
        dtheta = (k%jw(:, 1)*dy(1) + k%jw(:, 4)*dy(4)) + k%jw(:, 5)*dy(5)
        if (moved) then
            do i = 1, 3
                dk%n(i, :) = cross(dtheta, k%n(i, :))
            end do
            call omega_partials_tangent(k%ps, dth, dk%jw)
        else
            dk%n = 0.0_dp
            dk%jw = 0.0_dp
        end if
        dk%omega = (dk%jw(:, 1)*y(6) + dk%jw(:, 5)*y(10)) &
                   + ((k%jw(:, 1)*dy(6) + k%jw(:, 4)*dy(9)) + k%jw(:, 5)*dy(10))
        call omega_conv_tangent(k%ps, thd, dth, dthd, dk%cw)
        ! R* = C + rho
        dk%rho = cross(dtheta, k%rho)
        call body_point_tangent(k, dk, k%rho, dk%rho, moved, dk%jv, dk%cv)
        dk%cv = dk%cv + p%big_l*dk%econv
        ! D = C + u, u = -ntilde_3
        u = -k%n(3, :)
        du = -dk%n(3, :)
        dk%d = dk%c + du
        call body_point_tangent(k, dk, u, du, moved, dk%jd, dk%cd)
        dk%jd(:, 1) = 0.0_dp
        dk%jd(:, 2:3) = dk%jv(:, 2:3)
        dk%cd = dk%cd + p%big_l*dk%econv
        ! along the principal axes: the axes turn, db_i = dTheta x b_i
        if (moved) then
            do i = 1, 3
                dk%b(i, :) = cross(dtheta, k%b(i, :))
            end do
        else
            dk%b = 0.0_dp
        end if
        dk%wb(:, 1:3) = 0.0_dp
        dk%wb(:, 4) = -dk%b(:, 3)
        dk%wb(:, 5) = (k%ps%c4*dk%b(:, 1) - k%ps%s4*dk%b(:, 2)) &
                      - dy(4)*(k%ps%s4*k%b(:, 1) + k%ps%c4*k%b(:, 2))
        dk%omb = (dk%wb(:, 4)*y(9) + dk%wb(:, 5)*y(10)) &
                 + ((k%wb(:, 1)*dy(6) + k%wb(:, 4)*dy(9)) + k%wb(:, 5)*dy(10))
        dk%cwb = matmul(dk%b, k%cw) + matmul(k%b, dk%cw)
        dk%ps = pose_t()
    end subroutine chart_kinematics_tangent

    !> The change of a body point's partial velocities (columns 1, 4, 5: Omega_j x u) and of
    !! its convective acceleration (A x u + omega x (omega x u)), u = point - C.  When only
    !! the rates change (moved = .false.: dk%jw = 0, du = 0) the partial velocities do not.
    pure subroutine body_point_tangent(k, dk, u, du, moved, dj, dconv)
        type(chart_kin_t), intent(in) :: k, dk  !! kinematics and their change
        real(dp), intent(in) :: u(3), du(3)     !! the point's offset from C and its change
        logical, intent(in) :: moved            !! the angles change
        real(dp), intent(inout) :: dj(3, 5)     !! columns 1, 4, 5 set
        real(dp), intent(out) :: dconv(3)
        integer :: j
        if (moved) then
            do j = 1, 5
                if (j == 2 .or. j == 3) cycle
                dj(:, j) = cross(dk%jw(:, j), u) + cross(k%jw(:, j), du)
            end do
            dconv = cross(dk%cw, u) + cross(k%cw, du) + cross(dk%omega, cross(k%omega, u)) &
                    + cross(k%omega, cross(dk%omega, u) + cross(k%omega, du))
        else
            dj(:, 1) = 0.0_dp
            dj(:, 4:5) = 0.0_dp
            dconv = cross(dk%cw, u) + cross(dk%omega, cross(k%omega, u)) &
                    + cross(k%omega, cross(dk%omega, u))
        end if
    end subroutine body_point_tangent

    !> The constraint's gradient, D's velocity and the velocity terms of the twice
    !! differentiated constraint G = |AD|^2 - L'^2 (with Baumgarte's terms when
    !! p%stab_rate > 0): G'' = gradg . qddot + gconv.
    pure subroutine constraint_terms(p, y, k, gradg, vd, gconv)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(:)
        type(chart_kin_t), intent(in) :: k
        real(dp), intent(out) :: gradg(5), vd(3), gconv
        integer :: j
        gradg(1) = 0.0_dp                       ! theta_1 turns the body about CD
        do j = 2, 5
            gradg(j) = 2.0_dp*((k%d(1)*k%jd(1, j) + k%d(2)*k%jd(2, j)) + k%d(3)*k%jd(3, j))
        end do
        vd = ((k%jd(:, 2)*y(7) + k%jd(:, 3)*y(8)) + k%jd(:, 4)*y(9)) + k%jd(:, 5)*y(10)
        gconv = 2.0_dp*(dot_product(vd, vd) + dot_product(k%d, k%cd))
        if (p%stab_rate > 0.0_dp) then
            ! Baumgarte: drift off G = 0 decays at rate a; nothing changes on G = G' = 0
            gconv = gconv + 4.0_dp*p%stab_rate*dot_product(k%d, vd) &
                    + p%stab_rate**2*(dot_product(k%d, k%d) - p%big_lp**2)
        end if
    end subroutine constraint_terms

    !> Assemble and solve P qddot = Q, eq. (38): rows r /= k are Kane's equations (37) for the
    !! partial rates of change of the independent speeds, Jv(:,r) + gamma_r Jv(:,k) (eq. (31)),
    !! with gamma_r = -gradg(r)/gradg(k); row k is the twice-differentiated constraint
    !! gradg . qddot + gconv = 0.  k = `dependent`, or the largest |gradg| when absent.  The
    !! system is solved through its structure (constrained_solve); the factor stays in eo
    !! (for the Jacobian).
    subroutine solve_eq38(jv, cv, wb, cwb, omb, inertia, gradg, gconv, eo, stat, dependent, &
                          active)
        real(dp), intent(in) :: jv(3, 5), cv(3)         !! R*: partial velocities, a at qddot = 0
        real(dp), intent(in) :: wb(3, 5), cwb(3), omb(3)    !! the same for the rotation, and
                                                            !! omega, in principal axes
        real(dp), intent(in) :: inertia(3)              !! principal moments
        real(dp), intent(in) :: gradg(5), gconv
        type(eom_t), intent(inout) :: eo
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: dependent
        real(dp), intent(in), optional :: active(3)     !! an active torque on the body (the
                                                        !! damping; principal axes)
        real(dp) :: jvi(3, 4), wbi(3, 4), u(4), force(3), torque(3), t0
        integer :: k, r, a, ia
        eo%qdd = 0.0_dp
        if (present(dependent)) then
            k = dependent
        else
            k = 1
            do r = 2, 5
                if (abs(gradg(r)) > abs(gradg(k))) k = r
            end do
        end if
        eo%k = k
        if (.not. (abs(gradg(k)) > 0.0_dp)) then
            call set_error(stat, ERR_MODEL, 'constraint gradient vanishes (beta = 0)')
            return
        end if
        ! the constraint row: qddot_k = t0 + sum_r gamma_r qddot_r
        t0 = -gconv/gradg(k)
        a = 0
        do r = 1, 5
            if (r == k) then
                eo%gam(r) = 0.0_dp
            else
                a = a + 1
                eo%ind(a) = r
                eo%gam(r) = -gradg(r)/gradg(k)
                ! partial velocities of the independent speeds, eq. (31)
                jvi(:, a) = jv(:, r) + eo%gam(r)*jv(:, k)
                wbi(:, a) = wb(:, r) + eo%gam(r)*wb(:, k)
            end if
        end do
        ! Kane's equations (37) for them: the resultant force on R* (gravity and -m a at the
        ! independent qddot = 0, where qddot_k = t0) and torque on the body (the inertia
        ! torque there); active forces and torques are added here
        force = -(cv + t0*jv(:, k))
        force(3) = force(3) - 1.0_dp            ! g = 1
        torque = inertia_torque(inertia, cwb + t0*wb(:, k), omb)
        if (present(active)) torque = torque + active
        call project(4, jvi, wbi, force, torque, u)
        call generalized_inertia(4, jvi, wbi, inertia, eo%chol)
        call chol4(eo%chol, stat)
        if (stat%code /= 0) then
            call set_error(stat, ERR_NUMERIC, 'eq. (38): '//stat%msg)
            return
        end if
        call chol4_solve(eo%chol, u)
        eo%qdd(k) = t0
        do a = 1, 4
            ia = eo%ind(a)
            eo%qdd(ia) = u(a)
            eo%qdd(k) = eo%qdd(k) + eo%gam(ia)*u(a)
        end do
    end subroutine solve_eq38

    !> The solution x of eq. (38)'s structure for the right-hand side (e, c): M x = e +
    !! gradg mu (mu free), gradg . x = c.  With x = T u + t0 e_k, t0 = c/gradg(k), T = [I; gamma]
    !! (eq. (31)): (T^T M T) u = T^T (e - t0 M e_k), by the Cholesky factor in eo (eo%mk = M e_k
    !! set by the caller).  (The rows T^T M are those of P in eq. (38).)
    pure subroutine constrained_solve(eo, e, c, x)
        type(eom_t), intent(in) :: eo           !! factored system (solve_eq38)
        real(dp), intent(in) :: e(5), c         !! Kane's right-hand side; the constraint's
        real(dp), intent(out) :: x(5)
        real(dp) :: u(4), t0
        integer :: a, ia
        t0 = c/eo%gradg(eo%k)
        do a = 1, 4
            ia = eo%ind(a)
            u(a) = (e(ia) + eo%gam(ia)*e(eo%k)) - t0*(eo%mk(ia) + eo%gam(ia)*eo%mk(eo%k))
        end do
        call chol4_solve(eo%chol, u)
        x(eo%k) = t0
        do a = 1, 4
            ia = eo%ind(a)
            x(ia) = u(a)
            x(eo%k) = x(eo%k) + eo%gam(ia)*u(a)
        end do
    end subroutine constrained_solve

    !> Accelerations in the regular chart: qddot = (thddot1, sigma1'', sigma2'', thddot4, thddot5).
    subroutine chart_accelerations(p, y, qdd, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(:)            !! chart state (10)
        real(dp), intent(out) :: qdd(5)         !! chart accelerations
        type(status_t), intent(out) :: stat     !! ERR_MODEL: cable BC horizontal or worse
        type(chart_kin_t) :: k
        type(eom_t) :: eo
        call chart_solve(p, y, k, eo, stat)
        qdd = eo%qdd
    end subroutine chart_accelerations

    !> Kinematics and eq. (38) at a chart state (ERR_MODEL when the chart is not regular).
    subroutine chart_solve(p, y, k, eo, stat, sc_lambda)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(:)
        type(chart_kin_t), intent(out) :: k
        type(eom_t), intent(out) :: eo
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: sc_lambda(2)  !! sin, cos of p%lambda (body_pose)
        real(dp) :: gconv
        eo%qdd = 0.0_dp
        if (.not. chart_regular(y)) then
            call set_error(stat, ERR_MODEL, 'cable BC has swung up to the horizontal (theta2 = 90 deg)')
            return
        end if
        call chart_kinematics(p, y, k, sc_lambda)
        call constraint_terms(p, y, k, eo%gradg, eo%vd, gconv)
        if (p%c_v /= 0.0_dp .or. p%c_q /= 0.0_dp) then
            call solve_eq38(k%jv, k%cv, k%wb, k%cwb, k%omb, p%inertia, eo%gradg, gconv, eo, &
                            stat, active=damping_torque(p, k%omega, k%b))
        else
            call solve_eq38(k%jv, k%cv, k%wb, k%cwb, k%omb, p%inertia, eo%gradg, gconv, eo, stat)
        end if
    end subroutine chart_solve

    !> The damping torque on the body about the vertical (&damping), along the principal
    !! axes, over m g b': M = -(c_v W + c_q |W| W) n3 with W = omega . n3 per unit tau, so
    !! M . b_i = M3 (b_i . n3).  It enters eq. (38) as a generalized active force through
    !! the partial angular velocities, Wb(:,r) . M (gen_forces' project).
    pure function damping_torque(p, omega, b) result(tb)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (c_v, c_q)
        real(dp), intent(in) :: omega(3)        !! angular velocity, in n_i
        real(dp), intent(in) :: b(3, 3)         !! b_ij = b_i . n_j, eq. (11)
        real(dp) :: tb(3)
        real(dp) :: w
        w = omega(3)
        tb = (-(p%c_v*w + p%c_q*abs(w)*w))*b(:, 3)
    end function damping_torque

    !> The chart is regular while the cable BC hangs below the horizontal.
    pure logical function chart_regular(y)
        real(dp), intent(in) :: y(:)            !! chart state
        chart_regular = y(2)**2 + y(3)**2 < 0.999999_dp
    end function chart_regular

    !> The accelerations and their Jacobian Z = d f / d y of the chart right-hand side
    !! f = (qdot, qddot) (eq. (51)), exact.  Each column of the lower half is the derivative of
    !! the accelerations along a unit change of y: the derivatives of the kinematics carried
    !! through Kane's equations and the constraint and solved with the factors of eq. (38),
    !! the damping torque's derivative included; all ten in one pass (jacobian_columns), or
    !! with `tangents` one chart_kinematics_tangent and eom_tangent per column (the
    !! single-direction path of sens_jv, which the tests compare).
    subroutine chart_jacobian(p, y, qdd, z, stat, tangents)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp), intent(out) :: qdd(5)         !! accelerations at y
        real(dp), intent(out) :: z(NSTATE, NSTATE)  !! df_i/dy_j
        type(status_t), intent(out) :: stat     !! as chart_accelerations
        logical, intent(in), optional :: tangents   !! .true.: one tangent per column
        type(chart_kin_t) :: k
        type(eom_t) :: eo
        real(dp) :: a(3), tq(3), mu
        logical :: each
        z = 0.0_dp
        call chart_solve(p, y, k, eo, stat)
        qdd = eo%qdd
        if (stat%code /= 0) return
        call tangent_setup(p, k, eo, a, tq, mu)
        each = .false.
        if (present(tangents)) each = tangents
        if (each) then
            call jacobian_by_tangents(p, y, k, eo, a, tq, mu, z)
        else
            call jacobian_columns(p, y, k, eo, a, tq, mu, z)
        end if
    end subroutine chart_jacobian

    !> What the tangents of eq. (38) need at a solved point: R*'s acceleration a, the torque
    !! on the body tq (inertia torque and damping, principal axes), the constraint's
    !! multiplier mu (the residual of the unconstrained Kane's equations, R = f - M qddot, is
    !! gradg mu at the solution), and column k of the generalized inertia M (eo%mk, for
    !! constrained_solve).
    pure subroutine tangent_setup(p, k, eo, a, tq, mu)
        type(pendulum_t), intent(in) :: p
        type(chart_kin_t), intent(in) :: k
        type(eom_t), intent(inout) :: eo
        real(dp), intent(out) :: a(3), tq(3), mu
        real(dp) :: alpha(3), res(5), iwk(3)
        integer :: j
        a = matmul(k%jv, eo%qdd) + k%cv
        alpha = matmul(k%wb, eo%qdd) + k%cwb
        tq = inertia_torque(p%inertia, alpha, k%omb)
        if (p%c_v /= 0.0_dp .or. p%c_q /= 0.0_dp) tq = tq + damping_torque(p, k%omega, k%b)
        call project(5, k%jv, k%wb, -(a + [0.0_dp, 0.0_dp, 1.0_dp]), tq, res)
        mu = res(eo%k)/eo%gradg(eo%k)
        iwk = p%inertia*k%wb(:, eo%k)
        do j = 1, 5
            eo%mk(j) = dot_product(k%jv(:, j), k%jv(:, eo%k)) + dot_product(k%wb(:, j), iwk)
        end do
    end subroutine tangent_setup

    !> Z of a solved point (tangent_setup done), each column one tangent of its own
    !! (chart_kinematics_tangent, eom_tangent along a unit change of the state): the
    !! reference the one-pass jacobian_columns is tested against.
    pure subroutine jacobian_by_tangents(p, y, k, eo, a, tq, mu, z)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(NSTATE)
        type(chart_kin_t), intent(in) :: k
        type(eom_t), intent(in) :: eo
        real(dp), intent(in) :: a(3), tq(3), mu
        real(dp), intent(out) :: z(NSTATE, NSTATE)
        type(chart_kin_t) :: dk
        real(dp) :: dy(NSTATE)
        integer :: j
        z = 0.0_dp
        do j = 1, 5
            z(j, j + 5) = 1.0_dp
        end do
        do j = 1, NSTATE
            dy = 0.0_dp
            dy(j) = 1.0_dp
            call chart_kinematics_tangent(p, y, k, dy, dk)
            call eom_tangent(p, y, k, eo, a, tq, mu, dy, dk, z(6:10, j))
        end do
    end subroutine jacobian_by_tangents

    !> Z of a solved point (tangent_setup done) in one pass: the upper half (0 I), the lower
    !! half the change of the accelerations along each unit change of the state.  Each column
    !! is what chart_kinematics_tangent and eom_tangent give for its unit direction, but what
    !! a unit direction leaves unchanged is never formed, and what the directions share is
    !! formed once:
    !! * the cable's position sigma_j (columns 2, 3) moves C along de = (e_j, sigma_j/zeta)
    !!   and changes only the vertical components of the cable's partial velocities and
    !!   convective acceleration;
    !! * the cable's rates (7, 8) change only that convective acceleration;
    !! * the body's rates (6, 9, 10) change omega by Omega_j and the convective terms
    !!   (omega_conv's derivative), the kinematics' positions and partials not at all;
    !! * the body's angles (1, 4, 5) turn the body by dTheta = Omega_j: a body vector u by
    !!   dTheta x u (rho, D - C, the principal axes), with omega_partials' and omega_conv's
    !!   derivatives.
    !! The ten right-hand sides of the differentiated eq. (38) (see eom_tangent) are then
    !! solved together with its factor (constrained_solve's algorithm).  The damping torque's
    !! and Baumgarte's terms are included.
    pure subroutine jacobian_columns(p, y, k, eo, a, tq, mu, z)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(NSTATE)
        type(chart_kin_t), intent(in) :: k
        type(eom_t), intent(in) :: eo
        real(dp), intent(in) :: a(3), tq(3), mu
        real(dp), intent(out) :: z(NSTATE, NSTATE)
        integer, parameter :: BODY(3) = [1, 4, 5]   ! the body's coordinates theta_1, 4, 5
        real(dp) :: e(5, NSTATE), c(NSTATE), dgradg(5), fg(3), iw(3), u(3), wr(3), wu(3)
        real(dp) :: dd(3), dvd(3), dcv(3), dcd(3), dcw(3), dw(3), dth(3), drho(3), du(3)
        real(dp) :: djw1(3), djw5(3), djv1(3), djv4(3), djv5(3), djd4(3), djd5(3), db(3, 3)
        real(dp) :: dwb4(3), dwb5(3), domb(3), dcwb(3), da(3), dtq(3), e1(5)
        real(dp) :: dcw_rate(3, 3), dcw_pos(3, 3)
        real(dp) :: iz, sdsd, ssd, dz, dj(2), decv, dgconv, sr, wv, dm0, dm1, d1, d4, d5
        real(dp) :: d14, d15, d45
        integer :: m, j, ib, bj, i
        logical :: damped
        associate (qdd => eo%qdd, s4 => k%ps%s4, c4 => k%ps%c4, s5 => k%ps%s5, &
                   c5 => k%ps%c5, in => p%inertia, ll => p%big_l)
            z(1:5, :) = 0.0_dp
            do j = 1, 5
                z(j, j + 5) = 1.0_dp
            end do
            sr = p%stab_rate
            fg = -a
            fg(3) = fg(3) - 1.0_dp                  ! the force on R*: -(a + g n3)
            iw = in*k%omb
            u = -k%n(3, :)                          ! D - C
            wr = cross(k%omega, k%rho)
            wu = cross(k%omega, u)
            damped = p%c_v /= 0.0_dp .or. p%c_q /= 0.0_dp
            wv = k%omega(3)
            dm0 = p%c_v*wv + p%c_q*abs(wv)*wv       ! the damping torque's magnitude
            dm1 = p%c_v + 2.0_dp*p%c_q*abs(wv)      ! its derivative in W
            ! --- the cable: sigma_m (column m + 1) and its rate (column m + 6)
            iz = 1.0_dp/k%zeta
            sdsd = y(7)*y(7) + y(8)*y(8)
            ssd = y(2)*y(7) + y(3)*y(8)
            do m = 1, 2
                ! position: dzeta = -sigma_m/zeta, de = (e_m, sigma_m/zeta), dC = L de
                j = m + 1
                dz = -y(j)*iz
                dd = 0.0_dp
                dd(m) = ll
                dd(3) = ll*y(j)*iz
                ! the vertical components of the cable's partial velocities (columns 2, 3)
                ! and of its convective acceleration
                dj = [-y(2), -y(3)]*dz*iz**2
                dj(m) = dj(m) + iz
                dj = ll*dj
                decv = ll*(-sdsd*dz*iz**2 + 2.0_dp*ssd*y(j + 5)*iz**3 - 3.0_dp*ssd**2*dz*iz**4)
                da(3) = dj(1)*qdd(2) + dj(2)*qdd(3) + decv
                e(:, j) = -k%jv(3, :)*da(3)
                e(2, j) = e(2, j) + dj(1)*fg(3)
                e(3, j) = e(3, j) + dj(2)*fg(3)
                dgradg(1) = 0.0_dp
                do i = 2, 5
                    dgradg(i) = 2.0_dp*dot3(dd, k%jd(:, i))
                end do
                dgradg(2) = dgradg(2) + 2.0_dp*k%d(3)*dj(1)
                dgradg(3) = dgradg(3) + 2.0_dp*k%d(3)*dj(2)
                dvd(3) = dj(1)*y(7) + dj(2)*y(8)
                dgconv = 2.0_dp*(2.0_dp*eo%vd(3)*dvd(3) + dot3(dd, k%cd) + k%d(3)*decv)
                if (sr > 0.0_dp) dgconv = dgconv + 4.0_dp*sr*(dot3(dd, eo%vd) + k%d(3)*dvd(3)) &
                                          + 2.0_dp*sr**2*dot3(k%d, dd)
                e(:, j) = e(:, j) - mu*dgradg
                c(j) = -(dgconv + dot5(dgradg, qdd))
                ! rate: only e'' changes
                j = m + 6
                decv = ll*(2.0_dp*y(j)*iz + 2.0_dp*ssd*y(m + 1)*iz**3)
                e(:, j) = -k%jv(3, :)*decv
                dvd = k%jd(:, m + 1)
                dgconv = 2.0_dp*(2.0_dp*dot3(eo%vd, dvd) + k%d(3)*decv)
                if (sr > 0.0_dp) dgconv = dgconv + 4.0_dp*sr*dot3(k%d, dvd)
                c(j) = -dgconv
            end do
            ! --- the body: derivatives of omega_conv in its rates and angles (theta_1: none)
            d1 = y(6)
            d4 = y(9)
            d5 = y(10)
            dcw_rate(:, 1) = [-c4*c5*d4 + s4*s5*d5, s4*c5*d4 + c4*s5*d5, -c5*d5]
            dcw_rate(:, 2) = [-c4*c5*d1 - s4*d5, s4*c5*d1 - c4*d5, 0.0_dp]
            dcw_rate(:, 3) = [s4*s5*d1 - s4*d4, c4*s5*d1 - c4*d4, -c5*d1]
            d14 = d1*d4
            d15 = d1*d5
            d45 = d4*d5
            dcw_pos(:, 1) = 0.0_dp
            dcw_pos(:, 2) = [s4*c5*d14 + c4*s5*d15 - c4*d45, c4*c5*d14 - s4*s5*d15 + s4*d45, &
                             0.0_dp]
            dcw_pos(:, 3) = [c4*s5*d14 + s4*c5*d15, -s4*s5*d14 + c4*c5*d15, s5*d15]
            do ib = 1, 3
                bj = BODY(ib)
                ! rate of theta_bj (column bj + 5): domega = Omega_bj, the convective terms
                j = bj + 5
                dw = k%jw(:, bj)
                dcw = dcw_rate(:, ib)
                dcv = cross(dcw, k%rho) + cross(dw, wr) + cross(k%omega, cross(dw, k%rho))
                dcd = cross(dcw, u) + cross(dw, wu) + cross(k%omega, cross(dw, u))
                dcwb = (k%b(:, 1)*dcw(1) + k%b(:, 2)*dcw(2)) + k%b(:, 3)*dcw(3)
                domb = k%wb(:, bj)
                dtq = -in*dcwb - cross(domb, iw) - cross(k%omb, in*domb)
                if (damped) dtq = dtq - dm1*dw(3)*k%b(:, 3)
                call project(5, k%jv, k%wb, -dcv, dtq, e(:, j))
                dvd = k%jd(:, bj)
                dgconv = 2.0_dp*(2.0_dp*dot3(eo%vd, dvd) + dot3(k%d, dcd))
                if (sr > 0.0_dp) dgconv = dgconv + 4.0_dp*sr*dot3(k%d, dvd)
                c(j) = -dgconv
                ! angle theta_bj (column bj): the body turns by dTheta = Omega_bj; its points
                ! move by du = dTheta x u, their partial velocities Omega_j x u and
                ! convective accelerations cw x u + omega x (omega x u) change with u ...
                j = bj
                dth = k%jw(:, bj)
                drho = cross(dth, k%rho)
                du = cross(dth, u)
                djv1 = cross(k%jw(:, 1), drho)
                djv4 = [drho(2), -drho(1), 0.0_dp]      ! Omega_4 = -n3
                djv5 = cross(k%jw(:, 5), drho)
                djd4 = [du(2), -du(1), 0.0_dp]
                djd5 = cross(k%jw(:, 5), du)
                dcv = cross(k%cw, drho) + cross(k%omega, cross(k%omega, drho))
                dcd = cross(k%cw, du) + cross(k%omega, cross(k%omega, du))
                do i = 1, 3
                    db(i, :) = cross(dth, k%b(i, :))
                end do
                dcwb = (db(:, 1)*k%cw(1) + db(:, 2)*k%cw(2)) + db(:, 3)*k%cw(3)
                dw = 0.0_dp
                if (bj /= 1) then
                    ! ... and theta_4, theta_5 turn Omega_1 and Omega_5 (omega_partials'
                    ! derivative), hence omega and omega_conv (theta_1 turns neither)
                    if (bj == 4) then
                        djw1 = [-c4*c5, s4*c5, 0.0_dp]
                        djw5 = [-s4, -c4, 0.0_dp]
                        djv5 = djv5 + cross(djw5, k%rho)
                        djd5 = djd5 + cross(djw5, u)
                    else
                        djw1 = [s4*s5, c4*s5, -c5]
                        djw5 = 0.0_dp
                    end if
                    djv1 = djv1 + cross(djw1, k%rho)
                    dw = djw1*y(6) + djw5*y(10)
                    dcw = dcw_pos(:, ib)
                    dcv = dcv + (cross(dcw, k%rho) + cross(dw, wr) &
                                 + cross(k%omega, cross(dw, k%rho)))
                    dcd = dcd + (cross(dcw, u) + cross(dw, wu) + cross(k%omega, cross(dw, u)))
                    dcwb = dcwb + ((k%b(:, 1)*dcw(1) + k%b(:, 2)*dcw(2)) + k%b(:, 3)*dcw(3))
                end if
                dwb4 = -db(:, 3)
                dwb5 = c4*db(:, 1) - s4*db(:, 2)
                if (bj == 4) dwb5 = dwb5 - (s4*k%b(:, 1) + c4*k%b(:, 2))
                domb = dwb4*y(9) + dwb5*y(10)
                da = (djv1*qdd(1) + djv4*qdd(4) + djv5*qdd(5)) + dcv
                dtq = -in*((dwb4*qdd(4) + dwb5*qdd(5)) + dcwb) - cross(domb, iw) &
                      - cross(k%omb, in*domb)
                if (damped) dtq = dtq - dm1*dw(3)*k%b(:, 3) - dm0*db(:, 3)
                call project(5, k%jv, k%wb, -da, dtq, e(:, j))
                e1 = [dot3(djv1, fg), 0.0_dp, 0.0_dp, dot3(djv4, fg) + dot3(dwb4, tq), &
                      dot3(djv5, fg) + dot3(dwb5, tq)]
                dgradg = [0.0_dp, 2.0_dp*dot3(du, k%jd(:, 2)), 2.0_dp*dot3(du, k%jd(:, 3)), &
                          2.0_dp*(dot3(du, k%jd(:, 4)) + dot3(k%d, djd4)), &
                          2.0_dp*(dot3(du, k%jd(:, 5)) + dot3(k%d, djd5))]
                dvd = djd4*y(9) + djd5*y(10)
                dgconv = 2.0_dp*(2.0_dp*dot3(eo%vd, dvd) + dot3(du, k%cd) + dot3(k%d, dcd))
                if (sr > 0.0_dp) dgconv = dgconv + 4.0_dp*sr*(dot3(du, eo%vd) + dot3(k%d, dvd)) &
                                          + 2.0_dp*sr**2*dot3(k%d, du)
                e(:, j) = e(:, j) + e1 - mu*dgradg
                c(j) = -(dgconv + dot5(dgradg, qdd))
            end do
            call constrained_solve_many(eo, e, c, z(6:10, :))
        end associate
    end subroutine jacobian_columns

    !> constrained_solve for several right-hand sides (e(:, j), c(j)) at once: x(:, j), the
    !! Cholesky factor's forward and back substitution (DPOTRS's) written out for its 4 x 4.
    pure subroutine constrained_solve_many(eo, e, c, x)
        type(eom_t), intent(in) :: eo           !! factored system (solve_eq38), eo%mk set
        real(dp), intent(in) :: e(:, :), c(:)   !! (5, m), (m)
        real(dp), intent(out) :: x(:, :)        !! (5, m)
        real(dp) :: u1, u2, u3, u4, t0, mt(4), gi(4), l(4, 4)
        integer :: a, j, ind(4), kk
        kk = eo%k
        ind = eo%ind
        l = eo%chol
        do a = 1, 4
            gi(a) = eo%gam(ind(a))
            mt(a) = eo%mk(ind(a)) + gi(a)*eo%mk(kk)
        end do
        do j = 1, size(c)
            t0 = c(j)/eo%gradg(kk)
            u1 = (e(ind(1), j) + gi(1)*e(kk, j)) - t0*mt(1)
            u2 = (e(ind(2), j) + gi(2)*e(kk, j)) - t0*mt(2)
            u3 = (e(ind(3), j) + gi(3)*e(kk, j)) - t0*mt(3)
            u4 = (e(ind(4), j) + gi(4)*e(kk, j)) - t0*mt(4)
            ! L y = b
            u1 = u1/l(1, 1)
            u2 = (u2 - l(2, 1)*u1)/l(2, 2)
            u3 = ((u3 - l(3, 1)*u1) - l(3, 2)*u2)/l(3, 3)
            u4 = (((u4 - l(4, 1)*u1) - l(4, 2)*u2) - l(4, 3)*u3)/l(4, 4)
            ! L^T x = y
            u4 = u4/l(4, 4)
            u3 = (u3 - l(4, 3)*u4)/l(3, 3)
            u2 = ((u2 - l(3, 2)*u3) - l(4, 2)*u4)/l(2, 2)
            u1 = (((u1 - l(2, 1)*u2) - l(3, 1)*u3) - l(4, 1)*u4)/l(1, 1)
            x(ind(1), j) = u1
            x(ind(2), j) = u2
            x(ind(3), j) = u3
            x(ind(4), j) = u4
            x(kk, j) = (((t0 + gi(1)*u1) + gi(2)*u2) + gi(3)*u3) + gi(4)*u4
        end do
    end subroutine constrained_solve_many

    !> a . b of two 3-vectors, in the order the model's sums use.
    pure real(dp) function dot3(a, b)
        real(dp), intent(in) :: a(3), b(3)
        dot3 = (a(1)*b(1) + a(2)*b(2)) + a(3)*b(3)
    end function dot3

    !> a . b of two 5-vectors.
    pure real(dp) function dot5(a, b)
        real(dp), intent(in) :: a(5), b(5)
        dot5 = (((a(1)*b(1) + a(2)*b(2)) + a(3)*b(3)) + a(4)*b(4)) + a(5)*b(5)
    end function dot5

    !> The sensitivity terms at (t, y) (ode_system's sens_point): eq. (38) solved and made
    !! ready for the tangents of sens_jv, and df/dp of each direction of sys%dirs (0 for the
    !! columns beyond them), analytic: the moments' and the damping's (the change of the
    !! generalized inertia and active forces at fixed accelerations, solved with the factor
    !! of eq. (38), the constraint unchanged), the geometry's through param_tangent.
    subroutine bifilar_sens_point(sys, t, y, dfdp, stat)
        class(bifilar_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! tau (the system is autonomous)
        real(dp), intent(in) :: y(:)            !! chart state
        real(dp), intent(out) :: dfdp(:, :)     !! (NSTATE, ns)
        type(status_t), intent(out) :: stat
        real(dp) :: dtq(3), e(5), alpha(3)
        integer :: j, r
        logical :: geometry
        call unused(t)
        call refresh_lambda(sys)
        sys%sp_y = y(1:NSTATE)
        sys%sp_have_z = .false.
        sys%sp_cols = 0
        dfdp(1:5, :) = 0.0_dp
        call chart_solve(sys%p, y, sys%sp_k, sys%sp_eo, stat, sys%sc_lambda)
        if (stat%code /= 0) then
            dfdp(6:10, :) = 0.0_dp
            return
        end if
        call tangent_setup(sys%p, sys%sp_k, sys%sp_eo, sys%sp_a, sys%sp_tq, sys%sp_mu)
        associate (k => sys%sp_k, eo => sys%sp_eo, p => sys%p)
            alpha = matmul(k%wb, eo%qdd) + k%cwb
            do j = 1, size(dfdp, 2)
                if (.not. allocated(sys%dirs)) then
                    dfdp(6:10, j) = 0.0_dp
                    cycle
                else if (j > size(sys%dirs)) then
                    dfdp(6:10, j) = 0.0_dp
                    cycle
                end if
                associate (d => sys%dirs(j))
                    geometry = d%big_l /= 0.0_dp .or. d%big_lp /= 0.0_dp .or. &
                               d%big_b /= 0.0_dp .or. d%r /= 0.0_dp .or. d%lambda /= 0.0_dp
                    if (geometry) then
                        call param_tangent(p, y, k, eo, sys%sp_a, alpha, sys%sp_mu, d, &
                                           dfdp(6:10, j))
                        cycle
                    end if
                    ! the moments and the damping alone: the forces change, the kinematics not
                    dtq = direction_torque(k, alpha, d)
                    if (all(dtq == 0.0_dp)) then
                        dfdp(6:10, j) = 0.0_dp
                        cycle
                    end if
                    do r = 1, 5
                        e(r) = (k%wb(1, r)*dtq(1) + k%wb(2, r)*dtq(2)) + k%wb(3, r)*dtq(3)
                    end do
                    call constrained_solve(eo, e, 0.0_dp, dfdp(6:10, j))
                end associate
            end do
        end associate
    end subroutine bifilar_sens_point

    !> The change of the torque on the body (principal axes) along a direction d of the
    !! moments and the damping at fixed motion: the inertia torque's, -dI alpha - omega x
    !! (dI omega), and the damping torque's about the vertical.
    pure function direction_torque(k, alpha, d) result(dtq)
        type(chart_kin_t), intent(in) :: k      !! the kinematics at the point
        real(dp), intent(in) :: alpha(3)        !! the body's angular acceleration there
        type(sens_dir_t), intent(in) :: d       !! the direction in the parameters
        real(dp) :: dtq(3)
        real(dp) :: w
        w = k%omega(3)
        dtq = -d%inertia*alpha - cross(k%omb, d%inertia*k%omb) &
              - (d%c_v*w + d%c_q*abs(w)*w)*k%b(:, 3)
    end function direction_torque

    !> The change of the accelerations along a direction d of the pendulum's scaled
    !! parameters at a fixed state (df/dp of a sensitivity), exact: eq. (38) with the
    !! constraint's multiplier mu differentiated as in eom_tangent, M dqddot - gradg dmu =
    !! dR - mu dgradg, gradg . dqddot = -(dgconv + dgradg . qddot), where now the kinematics
    !! change with the geometry at a fixed state: C = B + L e moves with L and B (D with
    !! it, the cable's partial velocities with L), R*'s offset rho = r (s_lam ntilde1 -
    !! c_lam ntilde3) with r and lambda (its partial velocities Omega_j x rho and
    !! convective acceleration); the inertia torque with the moments, the damping torque
    !! with c_v, c_q; L' enters only Baumgarte's term of the constraint.  (k, eo, a, alpha,
    !! mu: the solved point, tangent_setup.)
    pure subroutine param_tangent(p, y, k, eo, a, alpha, mu, d, dqdd)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(:)            !! chart state
        type(chart_kin_t), intent(in) :: k      !! its kinematics
        type(eom_t), intent(in) :: eo           !! eq. (38) solved there (mk set)
        real(dp), intent(in) :: a(3)            !! R*'s acceleration
        real(dp), intent(in) :: alpha(3)        !! the body's angular acceleration (principal
                                                !! axes)
        real(dp), intent(in) :: mu              !! the constraint's multiplier
        type(sens_dir_t), intent(in) :: d       !! the direction in the parameters
        real(dp), intent(out) :: dqdd(5)
        real(dp) :: dc(3), drho(3), djv(3, 5), dcv(3), djd(3, 5), dcd(3), da(3), dtq(3)
        real(dp) :: e1(5), e2(5), dgradg(5), dvd(3), dgconv, iz
        integer :: j
        associate (qdd => eo%qdd, sl => k%ps%s_lambda, cl => k%ps%c_lambda)
            ! the kinematics at the fixed state
            dc = [d%big_l*k%e(1), -d%big_b + d%big_l*k%e(2), d%big_l*k%e(3)]
            drho = (d%r*sl + p%r*d%lambda*cl)*k%n(1, :) + (p%r*d%lambda*sl - d%r*cl)*k%n(3, :)
            iz = 1.0_dp/k%zeta
            djv(:, 1) = cross(k%jw(:, 1), drho)
            djv(:, 2) = d%big_l*[1.0_dp, 0.0_dp, y(2)*iz]
            djv(:, 3) = d%big_l*[0.0_dp, 1.0_dp, y(3)*iz]
            djv(:, 4) = [drho(2), -drho(1), 0.0_dp]
            djv(:, 5) = cross(k%jw(:, 5), drho)
            dcv = d%big_l*k%econv + cross(k%cw, drho) + cross(k%omega, cross(k%omega, drho))
            djd = 0.0_dp
            djd(:, 2:3) = djv(:, 2:3)
            dcd = d%big_l*k%econv
            ! Kane's equations at fixed accelerations: R = Jv^T (-(a + g n3)) + Wb^T T
            da = matmul(djv, qdd) + dcv
            dtq = direction_torque(k, alpha, d)
            call project(5, k%jv, k%wb, -da, dtq, e2)
            do j = 1, 5
                e1(j) = -dot_product(djv(:, j), a + [0.0_dp, 0.0_dp, 1.0_dp])
            end do
            ! the constraint G'' = gradg . qddot + gconv
            do j = 1, 5
                dgradg(j) = 2.0_dp*(dot_product(dc, k%jd(:, j)) + dot_product(k%d, djd(:, j)))
            end do
            dgradg(1) = 0.0_dp
            dvd = matmul(djd, y(6:10))
            dgconv = 2.0_dp*(2.0_dp*dot_product(eo%vd, dvd) + dot_product(dc, k%cd) &
                             + dot_product(k%d, dcd))
            if (p%stab_rate > 0.0_dp) then
                dgconv = dgconv + 4.0_dp*p%stab_rate*(dot_product(dc, eo%vd) &
                                                      + dot_product(k%d, dvd)) &
                         + 2.0_dp*p%stab_rate**2*(dot_product(k%d, dc) - p%big_lp*d%big_lp)
            end if
            e1 = e1 + e2 - mu*dgradg
            call constrained_solve(eo, e1, -(dgconv + dot_product(dgradg, qdd)), dqdd)
        end associate
    end subroutine param_tangent

    !> Products jv = Z v at the point of the last sens_point (ode_system's sens_jv): one
    !! tangent per column, or the whole of Z (computed once there) when the columns asked at
    !! the point exceed Z_COST.
    subroutine bifilar_sens_jv(sys, v, jv, stat)
        class(bifilar_t), intent(inout) :: sys
        real(dp), intent(in) :: v(:, :)         !! (NSTATE, m)
        real(dp), intent(out) :: jv(:, :)       !! (NSTATE, m)
        type(status_t), intent(out) :: stat
        type(chart_kin_t) :: dk
        integer :: c, m
        stat%code = 0
        m = size(v, 2)
        if (sys%sp_cols + m > Z_COST) call point_z(sys)
        if (sys%sp_have_z) then
            call z_products(m, sys%sp_z, v, jv)
            return
        end if
        jv(1:5, :) = v(6:10, :)
        do c = 1, m
            call chart_kinematics_tangent(sys%p, sys%sp_y, sys%sp_k, v(:, c), dk)
            call eom_tangent(sys%p, sys%sp_y, sys%sp_k, sys%sp_eo, sys%sp_a, sys%sp_tq, &
                             sys%sp_mu, v(:, c), dk, jv(6:10, c))
        end do
        sys%sp_cols = sys%sp_cols + m
    end subroutine bifilar_sens_jv

    !> jv = Z v for m columns (explicit shapes: contiguous columns the compiler can see),
    !! Z's upper half (0 I) taken as the copy of the rates.
    pure subroutine z_products(m, z, v, jv)
        integer, intent(in) :: m                !! columns
        real(dp), intent(in) :: z(NSTATE, NSTATE), v(NSTATE, m)
        real(dp), intent(out) :: jv(NSTATE, m)
        real(dp) :: acc(5)
        integer :: c, j
        do c = 1, m
            jv(1:5, c) = v(6:10, c)
            acc = z(6:10, 1)*v(1, c)
            do j = 2, NSTATE
                acc = acc + z(6:10, j)*v(j, c)
            end do
            jv(6:10, c) = acc
        end do
    end subroutine z_products

    !> Z itself at the point of the last sens_point (ode_system's sens_jacobian), formed
    !! there once (jacobian_columns).
    subroutine bifilar_sens_jacobian(sys, jac, stat)
        class(bifilar_t), intent(inout) :: sys
        real(dp), intent(out) :: jac(:, :)      !! (NSTATE, NSTATE)
        type(status_t), intent(out) :: stat
        stat%code = 0
        call point_z(sys)
        jac = sys%sp_z
    end subroutine bifilar_sens_jacobian

    !> Z at the point of the last sens_point (sp_z), formed there once (jacobian_columns).
    pure subroutine point_z(sys)
        class(bifilar_t), intent(inout) :: sys
        if (sys%sp_have_z) return
        call jacobian_columns(sys%p, sys%sp_y, sys%sp_k, sys%sp_eo, sys%sp_a, sys%sp_tq, &
                              sys%sp_mu, sys%sp_z)
        sys%sp_have_z = .true.
    end subroutine point_z

    !> W = omega . n3, the body's rate about the vertical (per unit tau), of a chart state:
    !! -sin(theta5) theta1' - theta4' (eq. (14)).
    pure real(dp) function vertical_rate(y) result(w)
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        w = -sin(y(5))*y(6) - y(9)
    end function vertical_rate

    !> The gradient of W = omega . n3 (the body's rate about the vertical, per unit tau) with
    !! respect to the chart state: W = -sin(theta5) theta1' - theta4' (eq. (14)).
    pure function vertical_rate_gradient(y) result(g)
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp) :: g(NSTATE)
        g = 0.0_dp
        g(5) = -cos(y(5))*y(6)
        g(6) = -sin(y(5))
        g(9) = -1.0_dp
    end function vertical_rate_gradient

    !> The change of the accelerations along a change dy of the state (kinematics changed by
    !! dk): eq. (38) with the Lagrange multiplier mu of the constraint, M qddot - gradg mu = f,
    !! gradg . qddot = -gconv, differentiated: M dqddot - gradg dmu = e, gradg . dqddot =
    !! -(dgconv + dgradg . qddot), e = dR - mu dgradg, dR the change of R = f - M qddot at fixed
    !! qddot; solved with the same factor (constrained_solve).
    pure subroutine eom_tangent(p, y, k, eo, a, tq, mu, dy, dk, dqdd)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(:)
        type(chart_kin_t), intent(in) :: k, dk
        type(eom_t), intent(in) :: eo
        real(dp), intent(in) :: a(3), tq(3)     !! R*'s acceleration and the inertia torque
                                                !! (in principal axes) at the solution
        real(dp), intent(in) :: mu                      !! the constraint's multiplier
        real(dp), intent(in) :: dy(:)
        real(dp), intent(out) :: dqdd(5)
        real(dp) :: da(3), dalpha(3), dtq(3), e1(5), e2(5), dgradg(5), dvd(3)
        real(dp) :: dgconv, wv
        integer :: j
        associate (qdd => eo%qdd, in => p%inertia, w => k%omb, dw => dk%omb)
            ! Kane's equations: R = Jv^T (-(a + g n3)) + Wb^T T, T = -I alpha - w x I w
            da = matmul(dk%jv, qdd) + dk%cv
            dalpha = matmul(dk%wb, qdd) + dk%cwb
            dtq = -in*dalpha - cross(dw, in*w) - cross(w, in*dw)
            if (p%c_v /= 0.0_dp .or. p%c_q /= 0.0_dp) then
                ! the damping torque -(c_v W + c_q |W| W) b(:, 3), W = omega . n3
                wv = k%omega(3)
                dtq = dtq - (p%c_v + 2.0_dp*p%c_q*abs(wv))*dk%omega(3)*k%b(:, 3) &
                      - (p%c_v*wv + p%c_q*abs(wv)*wv)*dk%b(:, 3)
            end if
            call project(5, k%jv, k%wb, -da, dtq, e2)
            if (any(dy(1:5) /= 0.0_dp)) then
                call project(5, dk%jv, dk%wb, -(a + [0.0_dp, 0.0_dp, 1.0_dp]), tq, e1)
                ! the constraint
                do j = 1, 5
                    dgradg(j) = 2.0_dp*(dot_product(dk%d, k%jd(:, j)) &
                                        + dot_product(k%d, dk%jd(:, j)))
                end do
            else
                ! only the rates change: the partial velocities and gradg do not
                e1 = 0.0_dp
                dgradg = 0.0_dp
            end if
            dvd = matmul(dk%jd, y(6:10)) + matmul(k%jd, dy(6:10))
            dgconv = 2.0_dp*(2.0_dp*dot_product(eo%vd, dvd) + dot_product(dk%d, k%cd) &
                             + dot_product(k%d, dk%cd))
            if (p%stab_rate > 0.0_dp) then
                dgconv = dgconv + 4.0_dp*p%stab_rate*(dot_product(dk%d, eo%vd) &
                                                      + dot_product(k%d, dvd)) &
                         + 2.0_dp*p%stab_rate**2*dot_product(k%d, dk%d)
            end if
            e1 = e1 + e2 - mu*dgradg
            call constrained_solve(eo, e1, -(dgconv + dot_product(dgradg, qdd)), dqdd)
        end associate
    end subroutine eom_tangent

    !> Accelerations thddot_1..5 from eq. (38) in the paper's own coordinates, theta_5
    !! eliminated as in eqs. (5), (31).  Singular at theta_2 = 0 and beta_5 = 0.
    subroutine paper_accelerations(p, th, thd, thdd, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: th(5), thd(5)   !! angles and rates
        real(dp), intent(out) :: thdd(5)        !! their second derivatives
        type(status_t), intent(out) :: stat
        type(pose_t) :: ps
        type(eom_t) :: eo
        real(dp) :: n(3, 3), jv(3, 5), cv(3), jw(3, 5), cw(3), omega(3), jd(3, 5), cd(3)
        real(dp) :: b(3, 3), gradg(5), d(3), vd(3), vdc(3, 5), gconv
        ps = pose_of(th, p%lambda)
        call frame(ps, n)
        call v_partials(p, ps, jv)
        call vdot_partials(p, ps, thd, vdc)
        cv = matmul(vdc, thd)
        call omega_partials(ps, jw)
        omega = matmul(jw, thd)
        call omega_conv(ps, thd, cw)
        associate (s4 => ps%s4, c4 => ps%c4, s5 => ps%s5, c5 => ps%c5)
            d = [0.0_dp, -p%big_b, 0.0_dp] + p%big_l*[ps%s2*ps%c3, ps%s2*ps%s3, -ps%c2] &
                + [c5*s4, c5*c4, s5]
            jd = 0.0_dp
            jd(:, 2:3) = jv(:, 2:3)
            jd(:, 4) = [c5*c4, -c5*s4, 0.0_dp]
            jd(:, 5) = [-s5*s4, -s5*c4, c5]
            cd = vdc(:, 2)*thd(2) + vdc(:, 3)*thd(3) &
                 + [-c5*s4*(thd(4)**2 + thd(5)**2) - 2.0_dp*s5*c4*thd(4)*thd(5), &
                    -c5*c4*(thd(4)**2 + thd(5)**2) + 2.0_dp*s5*s4*thd(4)*thd(5), -s5*thd(5)**2]
        end associate
        b = body_axes(p, n)
        gradg = 2.0_dp*matmul(d, jd)
        vd = matmul(jd, thd)
        gconv = 2.0_dp*(dot_product(vd, vd) + dot_product(d, cd))
        call solve_eq38(jv, cv, matmul(b, jw), matmul(b, cw), matmul(b, omega), p%inertia, &
                        gradg, gconv, eo, stat, dependent=5, active=damping_torque(p, omega, b))
        thdd = eo%qdd
    end subroutine paper_accelerations

    !> Chart state from the paper's angles and rates: sigma = s2 (c3, s3).
    pure function chart_state(th, thd) result(y)
        real(dp), intent(in) :: th(5), thd(5)   !! angles (rad) and rates
        real(dp) :: y(10)
        real(dp) :: s2, c2, s3, c3
        s2 = sin(th(2)); c2 = cos(th(2)); s3 = sin(th(3)); c3 = cos(th(3))
        y(1:5) = [th(1), s2*c3, s2*s3, th(4), th(5)]
        y(6:10) = [thd(1), c2*c3*thd(2) - s2*s3*thd(3), c2*s3*thd(2) + s2*c3*thd(3), &
                   thd(4), thd(5)]
    end function chart_state

    !> The paper's angles from a chart state.  theta_2 = +-asin|sigma| and theta_3 are chosen
    !! so that theta_3 is nearest th3_ref (theta_2 changes sign where the cable passes the
    !! vertical, as in eq. (49)); theta_3 is unwrapped to stay continuous.
    pure subroutine paper_angles(y, th3_ref, th, thd)
        real(dp), intent(in) :: y(10)           !! chart state
        real(dp), intent(in) :: th3_ref         !! previous theta_3 (rad)
        real(dp), intent(out) :: th(5), thd(5)  !! angles and rates
        real(dp) :: rho, a3, s2, c2, s3, c3
        rho = sqrt(y(2)**2 + y(3)**2)
        if (rho > 0.0_dp) then
            a3 = atan2(y(3), y(2))
        else
            a3 = th3_ref
        end if
        ! candidates (rho, a3 + 2 pi k) and (-rho, a3 + pi + 2 pi k): nearest to th3_ref
        a3 = a3 + 2.0_dp*pi*anint((th3_ref - a3)/(2.0_dp*pi))
        s2 = rho
        if (abs(a3 - th3_ref) > 0.5_dp*pi) then
            s2 = -rho
            a3 = a3 + sign(pi, th3_ref - a3)
        end if
        th = [y(1), asin(min(1.0_dp, s2)), a3, y(4), y(5)]
        c2 = cos(th(2)); s3 = sin(a3); c3 = cos(a3)
        thd(1) = y(6)
        thd(2) = (c3*y(7) + s3*y(8))/c2
        thd(3) = 0.0_dp
        if (abs(s2) > 0.0_dp) thd(3) = (-s3*y(7) + c3*y(8))/s2
        thd(4:5) = y(9:10)
    end subroutine paper_angles

    !> Positions of C, D, R*, E in the chart (over b', A at the origin).
    pure subroutine chart_positions(p, y, c, d, rstar, e, n)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(10)
        real(dp), intent(out) :: c(3), d(3), rstar(3), e(3), n(3, 3)
        call frame(body_pose(y(1), y(4), y(5), 0.0_dp), n)
        c = [0.0_dp, -p%big_b, 0.0_dp] + p%big_l*cable_direction(y(2:3))
        d = c - n(3, :)
        rstar = mass_centre(p, c, n)
        e = point_e(p, c, n)
    end subroutine chart_positions

    !> Total energy (kinetic + potential, over m g b') of a chart state.
    pure real(dp) function chart_energy(p, y) result(en)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(10)           !! chart state
        type(chart_kin_t) :: k
        call chart_kinematics(p, y, k)
        en = energy_from(p, y, k)
    end function chart_energy

    !> Kinetic + potential energy from the kinematics k of state y.
    pure real(dp) function energy_from(p, y, k) result(en)
        type(pendulum_t), intent(in) :: p
        real(dp), intent(in) :: y(10)
        type(chart_kin_t), intent(in) :: k
        real(dp) :: v(3), rs(3)
        v = matmul(k%jv, y(6:10))
        rs = k%c + k%rho
        en = 0.5_dp*dot_product(v, v) + 0.5_dp*sum(k%omb*(p%inertia*k%omb)) + rs(3)
    end function energy_from

    !> The constraint eq. (2) and its rate at a chart state: g = |AD|^2 - L'^2, gdot = dg/dtau.
    pure subroutine chart_constraint(p, y, g, gdot)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(10)           !! chart state
        real(dp), intent(out) :: g, gdot
        type(chart_kin_t) :: k
        call chart_kinematics(p, y, k)
        g = dot_product(k%d, k%d) - p%big_lp**2
        gdot = 2.0_dp*dot_product(k%d, matmul(k%jd, y(6:10)))
    end subroutine chart_constraint

    !> The gradients in the chart state y of the constraint G = |AD|^2 - L'^2, its rate
    !! G' = dG/dtau and the energy E (chart_constraint, chart_energy), exact: along the rates
    !! from the partial velocities (dG'/dqdot_j = dG/dq_j = 2 D . Jd_j, dE/dqdot_j = v . Jv_j
    !! + omega . I Wb_j, the generalized momentum), along the coordinates from the
    !! kinematics' tangents (chart_kinematics_tangent: dG'/dq_j = 2 (dD . vD + D . dJd qdot),
    !! dE/dq_j = v . dJv qdot + omega . I domega + dR*_3).
    pure subroutine chart_invariant_gradients(p, y, rows)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(NSTATE)       !! chart state (regular: |sigma| < 1)
        real(dp), intent(out) :: rows(NSTATE, 3)    !! columns grad G, grad G', grad E
        type(chart_kin_t) :: k, dk
        real(dp) :: dy(NSTATE), v(3), vd(3), iw(3), gj
        integer :: j
        call chart_kinematics(p, y, k)
        v = matmul(k%jv, y(6:10))
        vd = matmul(k%jd, y(6:10))
        iw = p%inertia*k%omb
        do j = 1, 5
            gj = 2.0_dp*dot_product(k%d, k%jd(:, j))
            rows(j, 1) = gj
            rows(j + 5, 1) = 0.0_dp
            rows(j + 5, 2) = gj
            rows(j + 5, 3) = dot_product(v, k%jv(:, j)) + dot_product(iw, k%wb(:, j))
            dy = 0.0_dp
            dy(j) = 1.0_dp
            call chart_kinematics_tangent(p, y, k, dy, dk)
            rows(j, 2) = 2.0_dp*(dot_product(dk%d, vd) + dot_product(k%d, matmul(dk%jd, y(6:10))))
            rows(j, 3) = dot_product(v, matmul(dk%jv, y(6:10))) + dot_product(iw, dk%omb) &
                         + (dk%c(3) + dk%rho(3))
        end do
    end subroutine chart_invariant_gradients

    !> The motion reported at one instant: angles in the paper's terms, and as `parts` asks
    !! (default: all) the accelerations with the cable tensions from Newton's law for the
    !! body, m a = -m g n3 - T_BC e_BC - T_AD e_AD, the energy, the constraint residual and
    !! the side-sway Q.  Fields not asked for are left 0.
    subroutine evaluate(p, y, th3_ref, mo, stat, parts)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(in) :: y(10)           !! chart state
        real(dp), intent(in) :: th3_ref         !! previous theta_3 (branch choice)
        type(motion_t), intent(out) :: mo
        type(status_t), intent(out) :: stat
        type(motion_parts_t), intent(in), optional :: parts
        type(motion_parts_t) :: want
        type(chart_kin_t) :: k
        type(eom_t) :: eo
        real(dp) :: gconv, pe(3), mid(3)
        if (present(parts)) want = parts
        call paper_angles(y, th3_ref, mo%th, mo%thd)
        if (.not. chart_regular(y)) then
            call set_error(stat, ERR_MODEL, 'cable BC has swung up to the horizontal (theta2 = 90 deg)')
            return
        end if
        call chart_kinematics(p, y, k)
        if (want%accelerations) then
            call constraint_terms(p, y, k, eo%gradg, eo%vd, gconv)
            call solve_eq38(k%jv, k%cv, k%wb, k%cwb, k%omb, p%inertia, eo%gradg, gconv, eo, &
                            stat, active=damping_torque(p, k%omega, k%b))
            if (stat%code /= 0) return
            mo%qdd = eo%qdd
            mo%astar = matmul(k%jv, mo%qdd) + k%cv
            mo%alpha = matmul(k%jw, mo%qdd) + k%cw
            call cable_tensions(y, k%d, mo%astar, mo%t_bc, mo%t_ad)
        end if
        mo%frame = k%b
        mo%rstar = k%c + k%rho
        mo%vstar = matmul(k%jv, y(6:10))
        mo%omega = k%omega
        if (want%energy) mo%energy = energy_from(p, y, k)
        if (want%residual) mo%residual = norm2(k%d) - p%big_lp
        if (want%sway) then
            ! side-sway: O = (0, -B/2, 0); E below the midpoint of CD
            pe = point_e(p, k%c, k%n)
            mid = k%c - 0.5_dp*k%n(3, :)
            mo%q_sway = sqrt(pe(1)**2 + (pe(2) + 0.5_dp*p%big_b)**2)
            mo%q_axis = sqrt((pe(1) - mid(1))**2 + (pe(2) - mid(2))**2)
        end if
    end subroutine evaluate

    !> The cable tensions (over m g) at a chart state from its rates' derivative ydot, as the
    !! integrator holds it at the end of a step: Newton's law for the body with R*'s
    !! acceleration a = Jv qddot + cv from qddot = ydot(6:10), without solving eq. (38)
    !! again.  For the validity check at every step (a slack cable).
    subroutine step_tensions(sys, y, ydot, t_bc, t_ad, stat)
        class(bifilar_t), intent(inout) :: sys  !! the pendulum
        real(dp), intent(in) :: y(NSTATE)       !! chart state
        real(dp), intent(in) :: ydot(NSTATE)    !! its derivative
        real(dp), intent(out) :: t_bc, t_ad     !! tensions of BC and AD over m g
        type(status_t), intent(out) :: stat     !! ERR_MODEL: the chart is not regular
        type(chart_kin_t) :: k
        t_bc = 0.0_dp
        t_ad = 0.0_dp
        if (.not. chart_regular(y)) then
            call set_error(stat, ERR_MODEL, 'cable BC has swung up to the horizontal (theta2 = 90 deg)')
            return
        end if
        call refresh_lambda(sys)
        call chart_kinematics(sys%p, y, k, sys%sc_lambda, dynamics=.false.)
        call cable_tensions(y, k%d, matmul(k%jv, ydot(6:10)) + k%cv, t_bc, t_ad)
    end subroutine step_tensions

    !> Tensions from R*'s acceleration a: least squares of [e_BC e_AD] T = -(a + g n3); when the
    !! cables are parallel only their sum is determined and it is shared equally (before,
    !! each cable was given the whole sum).
    pure subroutine cable_tensions(y, d, astar, t_bc, t_ad)
        real(dp), intent(in) :: y(:)            !! chart state
        real(dp), intent(in) :: d(3)            !! the point D there (A at the origin)
        real(dp), intent(in) :: astar(3)        !! acceleration of R*
        real(dp), intent(out) :: t_bc, t_ad
        real(dp) :: ebc(3), ead(3), f(3), a11, a12, a22, r1, r2, det
        ebc = cable_direction(y(2:3))
        ead = d/norm2(d)
        f = -(astar + [0.0_dp, 0.0_dp, 1.0_dp])
        a11 = dot_product(ebc, ebc); a12 = dot_product(ebc, ead); a22 = dot_product(ead, ead)
        r1 = dot_product(ebc, f); r2 = dot_product(ead, f)
        det = a11*a22 - a12**2
        if (abs(det) > 1.0e-14_dp) then
            t_bc = (a22*r1 - a12*r2)/det
            t_ad = (a11*r2 - a12*r1)/det
        else
            ! parallel cables: T_BC + T_AD = (e . f)/|e|^2, each takes half
            t_bc = 0.25_dp*(r1 + r2)/a11
            t_ad = t_bc
        end if
    end subroutine cable_tensions

    !> The 4 x 4 Cholesky factor of eq. (38)'s matrix: la_small_chol's algorithm and order
    !! of operations at n = 4, written out here because the link-time optimiser keeps
    !! la_small_chol out of line once the platform's models call it too (8 % more
    !! instructions in a record fit); this one has a caller alone, and is inlined.
    pure subroutine chol4(a, stat)
        real(dp), intent(inout) :: a(4, 4)
        type(status_t), intent(out) :: stat
        real(dp) :: ajj
        integer :: i, j, k
        stat%code = 0
        do j = 1, 4
            ajj = a(j, j)
            do k = 1, j - 1
                ajj = ajj - a(j, k)*a(j, k)
            end do
            if (.not. (ajj > 0.0_dp)) then
                call set_error(stat, ERR_NUMERIC, 'la_small_chol: matrix not positive '// &
                               'definite (leading minor of order '//achar(iachar('0') + j)//')')
                return
            end if
            ajj = sqrt(ajj)
            a(j, j) = ajj
            do i = j + 1, 4
                do k = 1, j - 1
                    a(i, j) = a(i, j) - a(i, k)*a(j, k)
                end do
                a(i, j) = a(i, j)/ajj
            end do
        end do
    end subroutine chol4

    !> Solve A x = b in place with chol4's factor (la_small_chol_solve's order at n = 4).
    pure subroutine chol4_solve(l, b)
        real(dp), intent(in) :: l(4, 4)
        real(dp), intent(inout) :: b(4)
        integer :: i, k
        do i = 1, 4
            do k = 1, i - 1
                b(i) = b(i) - l(i, k)*b(k)
            end do
            b(i) = b(i)/l(i, i)
        end do
        do i = 4, 1, -1
            do k = i + 1, 4
                b(i) = b(i) - l(k, i)*b(k)
            end do
            b(i) = b(i)/l(i, i)
        end do
    end subroutine chol4_solve

end module bifilar_model
