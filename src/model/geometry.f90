!> Geometry of the bifilar pendulum (Kane & Tseng 1966, eqs. (1)-(11), (44)).
!!
!! Frames and points, in the paper's conventions (see ../shared/paper/NOTES.md):
!! n3 points up, A is the origin, B = -b n2, C = B + l (s2 c3, s2 s3, -c2),
!! D = C + b' (c5 s4, c5 c4, s5); the cable AD has length l'.  All routines here work
!! in lengths divided by b' (L = l/b', B = b/b', L' = l'/b'), so b' = 1.
!!
!! The paper's eq. (2) is used with its misprint corrected (b' c4 c5 in the second bracket).
module geometry
    use kinds, only: dp, pi
    implicit none
    private

    !> Scaled parameters of one pendulum (lengths over b', mass over m, time over sqrt(b'/g)).
    type, public :: pendulum_t
        real(dp) :: big_l = 2.0_dp      !! L  = l/b'
        real(dp) :: big_lp = 2.0_dp     !! L' = l'/b'
        real(dp) :: big_b = 1.0_dp      !! B  = b/b'
        real(dp) :: inertia(3) = [0.125_dp, 0.1458333333333333_dp, 0.1458333333333333_dp]
                                        !! I_i/(m b'^2), principal moments for R*
        real(dp) :: r = 0.7071067811865476_dp  !! |C R*| / b'
        real(dp) :: lambda = pi/4       !! angle between r and ntilde_3 (rad)
        real(dp) :: btilde(3, 3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                            0.0_dp, 0.0_dp, 1.0_dp], [3, 3])  !! eq. (9)
        real(dp) :: h_e = 1.0_dp        !! depth of E below the midpoint of CD, over b'
        real(dp) :: stab_rate = 0.0_dp  !! Baumgarte rate a: the twice-differentiated constraint
                                        !! is imposed as G'' + 2 a G' + a^2 G = 0 (0: G'' = 0)
        !> Damping about the vertical (&damping), scaled: the torque on the body is
        !! M = -(c_v W + c_q |W| W) n3 over m g b', W = omega . n3 per unit tau
        !! (c_v = c_v,deck / (m b' sqrt(g b')), c_q = c_q,deck / (m b'^2)); 0: undamped
        real(dp) :: c_v = 0.0_dp, c_q = 0.0_dp
    end type pendulum_t

    !> The trigonometry of one pose, under the paper's names: s_i = sin(theta_i),
    !! c_i = cos(theta_i), and s_lambda, c_lambda of the angle lambda that places R* (eq. (21)).
    !! Filled once per evaluation (pose_of) and read by eqs. (2)-(4), (8), (14), (19), (24),
    !! (27): the one place the model calls sin and cos.
    type, public :: pose_t
        real(dp) :: s1 = 0.0_dp, c1 = 1.0_dp, s2 = 0.0_dp, c2 = 1.0_dp, s3 = 0.0_dp, c3 = 1.0_dp
        real(dp) :: s4 = 0.0_dp, c4 = 1.0_dp, s5 = 0.0_dp, c5 = 1.0_dp
        real(dp) :: s_lambda = 0.0_dp, c_lambda = 1.0_dp
    end type pose_t

    public :: constraint_g, beta_coeffs, direction_cosines, body_axes, pose_of, body_pose, frame
    public :: cable_direction, point_d, mass_centre, point_e

contains

    !> The pose's sines and cosines: theta_1..theta_5 and lambda.
    pure function pose_of(th, lambda) result(ps)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp), intent(in) :: lambda      !! lambda of eq. (21) (rad)
        type(pose_t) :: ps
        ps%s1 = sin(th(1)); ps%c1 = cos(th(1)); ps%s2 = sin(th(2)); ps%c2 = cos(th(2))
        ps%s3 = sin(th(3)); ps%c3 = cos(th(3)); ps%s4 = sin(th(4)); ps%c4 = cos(th(4))
        ps%s5 = sin(th(5)); ps%c5 = cos(th(5))
        ps%s_lambda = sin(lambda); ps%c_lambda = cos(lambda)
    end function pose_of

    !> The pose of the body alone (theta_1, theta_4, theta_5 and lambda; theta_2 = theta_3 = 0):
    !! what the regular chart needs, where the cable's direction is not given by angles.
    !! sc_lambda, when present, holds sin and cos of lambda already computed (they depend only
    !! on the pendulum: an integration computes them once, see bifilar_model).
    pure function body_pose(th1, th4, th5, lambda, sc_lambda) result(ps)
        real(dp), intent(in) :: th1, th4, th5   !! theta_1, theta_4, theta_5 (rad)
        real(dp), intent(in) :: lambda          !! lambda of eq. (21) (rad)
        real(dp), intent(in), optional :: sc_lambda(2)  !! sin(lambda), cos(lambda)
        type(pose_t) :: ps
        ps%s1 = sin(th1); ps%c1 = cos(th1); ps%s4 = sin(th4); ps%c4 = cos(th4)
        ps%s5 = sin(th5); ps%c5 = cos(th5)
        if (present(sc_lambda)) then
            ps%s_lambda = sc_lambda(1); ps%c_lambda = sc_lambda(2)
        else
            ps%s_lambda = sin(lambda); ps%c_lambda = cos(lambda)
        end if
    end function body_pose

    !> Direction cosines n_ij of eq. (8) from a pose: ntilde_i = sum_j n(i,j) n_j.
    pure subroutine frame(ps, n)
        type(pose_t), intent(in) :: ps      !! the pose (theta_1, 4, 5)
        real(dp), intent(out) :: n(3, 3)    !! rows: ntilde_1, ntilde_2, ntilde_3 in n_j
        associate (s1 => ps%s1, c1 => ps%c1, s4 => ps%s4, c4 => ps%c4, s5 => ps%s5, &
                   c5 => ps%c5)
            n(1, 1) = s1*c4 + c1*s4*s5
            n(1, 2) = -s1*s4 + c1*c4*s5
            n(1, 3) = -c1*c5
            n(2, 1) = c1*c4 - s1*s4*s5
            n(2, 2) = -c1*s4 - s1*c4*s5
            n(2, 3) = s1*c5
            n(3, 1) = -s4*c5
            n(3, 2) = -c4*c5
            n(3, 3) = -s5
        end associate
    end subroutine frame

    !> Residual of the constraint eq. (2) divided by b'^2:
    !! G = (L s2 c3 + s4 c5)^2 + (-B + L s2 s3 + c4 c5)^2 + (-L c2 + s5)^2 - L'^2.
    pure real(dp) function constraint_g(p, th) result(g)
        type(pendulum_t), intent(in) :: p   !! scaled parameters
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: d(3)
        d = point_d(p, th)
        g = dot_product(d, d) - p%big_lp**2
    end function constraint_g

    !> beta_1..beta_5 of eq. (4): eq. (3) reads sum_{i<=4} beta_i thdot_i - beta_5 thdot_5 = 0,
    !! and beta_i = (1/2) dG/dtheta_i (i = 2..4), beta_5 = -(1/2) dG/dtheta_5, beta_1 = 0.
    pure function beta_coeffs(p, th) result(beta)
        type(pendulum_t), intent(in) :: p   !! scaled parameters
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: beta(5)
        real(dp) :: s2, c2, s3, c3, s4, c4, s5, c5, x, y, z
        type(pose_t) :: ps
        ps = pose_of(th, p%lambda)
        s2 = ps%s2; c2 = ps%c2; s3 = ps%s3; c3 = ps%c3
        s4 = ps%s4; c4 = ps%c4; s5 = ps%s5; c5 = ps%c5
        x = p%big_l*s2*c3 + s4*c5
        y = -p%big_b + p%big_l*s2*s3 + c4*c5
        z = -p%big_l*c2 + s5
        beta(1) = 0.0_dp
        beta(2) = p%big_l*(c2*c3*x + c2*s3*y + s2*z)
        beta(3) = p%big_l*(-s2*s3*x + s2*c3*y)
        beta(4) = c4*c5*x - s4*c5*y
        beta(5) = s4*s5*x + c4*s5*y - c5*z
    end function beta_coeffs

    !> Direction cosines n_ij of eq. (8): ntilde_i = sum_j n(i,j) n_j.  Uses theta_1, 4, 5.
    pure function direction_cosines(th) result(n)
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: n(3, 3)
        call frame(body_pose(th(1), th(4), th(5), 0.0_dp), n)
    end function direction_cosines

    !> b_ij of eq. (11): b_i = sum_j b(i,j) n_j, b = btilde n.
    pure function body_axes(p, n) result(b)
        type(pendulum_t), intent(in) :: p   !! scaled parameters (btilde)
        real(dp), intent(in) :: n(3, 3)     !! direction cosines of eq. (8)
        real(dp) :: b(3, 3)
        integer :: j
        do j = 1, 3
            b(:, j) = (p%btilde(:, 1)*n(1, j) + p%btilde(:, 2)*n(2, j)) + p%btilde(:, 3)*n(3, j)
        end do
    end function body_axes

    !> Unit vector along BC from its horizontal components sigma = s2 (c3, s3):
    !! e = (sigma_1, sigma_2, -sqrt(1 - |sigma|^2)).  Regular at theta_2 = 0.
    pure function cable_direction(sigma) result(e)
        real(dp), intent(in) :: sigma(2)    !! horizontal components of the unit vector B->C
        real(dp) :: e(3)
        e = [sigma(1), sigma(2), -sqrt(max(0.0_dp, 1.0_dp - sigma(1)**2 - sigma(2)**2))]
    end function cable_direction

    !> Position of D (over b'), A at the origin: D = B + L e + (c5 s4, c5 c4, s5), eq. (1).
    pure function point_d(p, th) result(d)
        type(pendulum_t), intent(in) :: p   !! scaled parameters
        real(dp), intent(in) :: th(5)       !! theta_1..theta_5 (rad)
        real(dp) :: d(3)
        type(pose_t) :: ps
        ps = pose_of(th, p%lambda)
        d = [p%big_l*ps%s2*ps%c3 + ps%c5*ps%s4, -p%big_b + p%big_l*ps%s2*ps%s3 + ps%c5*ps%c4, &
             -p%big_l*ps%c2 + ps%s5]
    end function point_d

    !> Mass centre R* (over b'): C + r (s_lam ntilde_1 - c_lam ntilde_3), eqs. (21)-(22).
    pure function mass_centre(p, c, n) result(rs)
        type(pendulum_t), intent(in) :: p   !! scaled parameters
        real(dp), intent(in) :: c(3)        !! position of C
        real(dp), intent(in) :: n(3, 3)     !! direction cosines of eq. (8)
        real(dp) :: rs(3)
        rs = c + p%r*(sin(p%lambda)*n(1, :) - cos(p%lambda)*n(3, :))
    end function mass_centre

    !> Body point E: h_E below the midpoint of CD at rest, E = C - (1/2) ntilde_3 + h_E ntilde_1.
    pure function point_e(p, c, n) result(e)
        type(pendulum_t), intent(in) :: p   !! scaled parameters
        real(dp), intent(in) :: c(3)        !! position of C
        real(dp), intent(in) :: n(3, 3)     !! direction cosines of eq. (8)
        real(dp) :: e(3)
        e = c - 0.5_dp*n(3, :) + p%h_e*n(1, :)
    end function point_e

end module geometry
