!> The period of one hang of a body with a known inertia tensor, from the paper's full model
!! (analysis tensor).
!!
!! * The body: the inertia tensor J about the mass centre in the user's body frame, six
!!   entries x = (J_xx, J_yy, J_zz, J_xy, J_xz, J_yz) with J_xy = -int x y dm (the matrix
!!   entries themselves), so that the moment about a unit direction u is u . J u.
!! * The hang (module measurement's hang_t): the body turned so that `up` points up at rest and
!!   `along` from C toward D.  In the model's terms ntilde_1 = -up (down at rest), ntilde_3
!!   = -along (from D to C), ntilde_2 = ntilde_3 x ntilde_1; the principal axes of J
!!   (eigenvectors, LAPACK dsyev) expressed in that frame are the rows of btilde, the
!!   principal moments the model's inertia; the mass centre from C by eq. (21):
!!   r cos(lambda) = b'/2 + cg_offset, r sin(lambda) = cg_depth (hang_rig).
!! * The rest pose (rest_pose): the body hangs with its mass centre in the vertical plane
!!   through CD (theta_1 = 0) and CD in the plane of the support's cables (theta_4 = 0,
!!   sigma_1 = 0): the statics does not depend on the inertia, only on the geometry.  The
!!   remaining pose (sigma_2, theta_5) is where the planar four-bar A-B-C-D carries the
!!   mass centre lowest: the constraint eq. (2) solved for theta_5 in closed form, and
!!   sigma_2 by Newton's method on the accelerations at rest (zero there).  For equal cables
!!   and the mass centre below the midpoint of CD the body hangs level (theta_5 = 0);
!!   otherwise it tilts.
!! * Small amplitude (torsion_mode): the equations linearised at the rest pose, with the
!!   exact Jacobian of the chart's right-hand side (bifilar_model's chart_jacobian, no
!!   Baumgarte term): qddot = K q with K = Z(6:10, 1:5).  Its eigenvalues (LAPACK dgeev) are
!!   -omega_k^2 for the four oscillations (torsion, tilting about CD and the two sways) and
!!   0 for the direction that leaves the constraint.  A body whose vertical is not a
!!   principal axis does not twist purely: its torsion couples with tilting and sway and
!!   every mode mixes them.  The torsion mode is the one whose shape has the largest share of
!!   theta_4, each coordinate counted by the displacement it causes (rotations times b'/2,
!!   the cable's sigma times l).  Its period is 2 pi/omega (b'/g)^(1/2).
!! * At amplitude A > 0 (hang_period): the full model, released at rest in the torsion
!!   mode's shape scaled to theta_4 = A (the pose a small torsion passes through at its
!!   turning point; theta_5 from the constraint), run to the next maximum of theta_4 after
!!   theta_4 has swung below its rest value: the time from release to that maximum, located
!!   in the integrator's dense output (as identify's simulated periods).  As A -> 0 it tends
!!   to the mode's period.
!! * What hangs (loaded_hang): the body with a fixture (fixture_t, in the body frame or the
!!   hang's) and its mass centre where a fit puts it.  Their common mass centre G rests in
!!   the vertical plane through C and D (hang_points: C and D in the body frame from the
!!   table's hang), so the loaded hang's up is the normal to CD in the plane of C, D and G,
!!   its cg_depth and cg_offset G's, its mass the sum, its tensor the parallel-axis sum
!!   about G.
!! * The drift of the maxima (maxima_drift): at larger amplitudes the torsion feeds the
!!   other modes and theta_4's maxima no longer come a period apart; the drift is the
!!   largest change of the interval between successive maxima over the first cycles, over
!!   the first interval.  The analysis refuses amplitudes where it is too large (see
!!   tensor_fit).
!! * On a platform of three cables (hang_t%cables = 3): the body rests on the platform with
!!   `up` its normal and `along` its x axis; the rig (hang_rig) is the platform's, btilde in
!!   its (z, x, y) axes; the period is the platform's own model (module platform_model,
!!   hang_platform): at A = 0 its equations linearised at the rest pose, the mode with the
!!   largest share of the yaw (platform_small_period), at A > 0 its periodic torsion
!!   (module platform_orbit), periodic by construction (no drift).  What hangs
!!   (loaded_hang) keeps the hang's up: the platform model rests with G anywhere; a
!!   fixture in the hang's frame has its origin at the centre of the platform's
!!   attachment points (hang_centre).
!!
!! Units are the deck's; angles in degrees where the table gives them.  No routine stops.
module hang_model
    use kinds, only: dp, pi, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_NUMERIC
    use text, only: sci, fixed
    use geometry, only: pendulum_t
    use vectors, only: cross
    use bifilar_model, only: NSTATE, chart_jacobian, chart_accelerations, chart_constraint, &
        paper_angles
    use rig, only: rig_t, accuracy_t, make_pendulum
    use kane_run, only: kane_run_t, kane_run_start
    use run_loop, only: drive
    use theta4_maxima, only: maxima_sink_t
    use lapack_wrap, only: la_syev, la_eigv
    use measurement, only: hang_t
    use platform_model, only: linearise, platform_modes_t, check_platform
    use platform_geometry, only: platform_t, regular_platform, general_platform, platform_inertia, &
        QX, QY, QPSI
    use platform_orbit, only: platform_torsion_period
    implicit none
    private

    !> The torsion mode of a hang at small amplitude.
    type, public :: torsion_mode_t
        real(dp) :: y_rest(NSTATE) = 0.0_dp     !! the rest pose as a chart state
        real(dp) :: shape(5) = 0.0_dp           !! the mode's shape, theta_4 component 1
        real(dp) :: omega = 0.0_dp              !! its angular frequency per unit tau
        real(dp) :: period = 0.0_dp             !! its period, s
        real(dp) :: share = 0.0_dp              !! theta_4's share of the mode's shape
        real(dp) :: next_share = 0.0_dp         !! the largest share among the other modes
    end type torsion_mode_t

    !> A fixture that hangs with the body in every hang: its mass, its mass centre and its
    !! inertia about its mass centre (J_xy = -int x y dm), in the body frame of the table
    !! (hang_frame = .false.: it turns with the body) or in the frame of the hang
    !! (hang_frame = .true.: it stays with the hang; axes along CD from C to D, across =
    !! up x along, up; origin the midpoint of CD).
    type, public :: fixture_t
        real(dp) :: mass = 0.0_dp
        real(dp) :: cg(3) = 0.0_dp
        real(dp) :: inertia(3, 3) = 0.0_dp
        logical :: hang_frame = .false.
    end type fixture_t

    !> A platform of three cables given point by point (&suspension support_points,
    !! body_points, lengths): the points as the deck gives them and the scales the deck's
    !! normalise derives from them (b, b_prime: twice the mean distance of the support's
    !! and the platform's points from their centroids; l: the mean length).  A hang's rig
    !! with other b, b_prime or l (a perturbed input, a Monte Carlo draw) scales the
    !! support's points about their centroid by b/this%b, the platform's by
    !! b_prime/this%b_prime and every length by l/this%l.  given = .false.: the regular
    !! polygon of the rig's b, b_prime, l.
    type, public :: platform_points_t
        logical :: given = .false.
        real(dp) :: support(3, 3) = 0.0_dp      !! column i: cable i's support point
        real(dp) :: body(3, 3) = 0.0_dp         !! column i: its point on the platform
        real(dp) :: lengths(3) = 0.0_dp
        real(dp) :: b = 1.0_dp, b_prime = 1.0_dp, l = 1.0_dp
    end type platform_points_t

    public :: tensor_matrix, tensor_entries, principal_axes, hang_frame, turned_hang
    public :: hang_rig, rest_pose, torsion_mode, hang_period, maxima_drift, vertical_moment
    public :: moment_direction, loaded_hang, hang_points, fixture_in_body, plane_normal
    public :: hang_centre, platform_small_period


    !> Newton's method on the rest pose: iterations, and the relative change that ends it.
    integer, parameter :: REST_ITER = 60
    !> |qddot| at the rest pose above which it is not one (scaled units).
    real(dp), parameter :: REST_TOL = 1.0e-9_dp

contains

    !> The symmetric 3 x 3 tensor of the six entries (J_xx, J_yy, J_zz, J_xy, J_xz, J_yz).
    pure function tensor_matrix(x) result(j)
        real(dp), intent(in) :: x(6)            !! the entries
        real(dp) :: j(3, 3)
        j = reshape([x(1), x(4), x(5), x(4), x(2), x(6), x(5), x(6), x(3)], [3, 3])
    end function tensor_matrix

    !> The six entries (J_xx, J_yy, J_zz, J_xy, J_xz, J_yz) of a symmetric tensor.
    pure function tensor_entries(j) result(x)
        real(dp), intent(in) :: j(3, 3)         !! the tensor
        real(dp) :: x(6)
        x = [j(1, 1), j(2, 2), j(3, 3), 0.5_dp*(j(1, 2) + j(2, 1)), 0.5_dp*(j(1, 3) + j(3, 1)), &
             0.5_dp*(j(2, 3) + j(3, 2))]
    end function tensor_entries

    !> The moment u . J u about the unit direction u.
    pure real(dp) function vertical_moment(x, u) result(m)
        real(dp), intent(in) :: x(6)            !! the tensor's entries
        real(dp), intent(in) :: u(3)            !! unit direction
        m = dot_product(moment_direction(u), x)
    end function vertical_moment

    !> The row of the moment about u in the entries: u . J u = sum_k a(k) x(k),
    !! a = (ux^2, uy^2, uz^2, 2 ux uy, 2 ux uz, 2 uy uz).
    pure function moment_direction(u) result(a)
        real(dp), intent(in) :: u(3)            !! unit direction
        real(dp) :: a(6)
        a = [u(1)**2, u(2)**2, u(3)**2, 2.0_dp*u(1)*u(2), 2.0_dp*u(1)*u(3), 2.0_dp*u(2)*u(3)]
    end function moment_direction

    !> The principal moments (ascending) and axes (columns, unit, a right-handed set) of a
    !! symmetric tensor (LAPACK dsyev).
    subroutine principal_axes(x, w, v, stat)
        real(dp), intent(in) :: x(6)            !! the tensor's entries
        real(dp), intent(out) :: w(3)           !! principal moments, ascending
        real(dp), intent(out) :: v(3, 3)        !! column k the axis of w(k)
        type(status_t), intent(out) :: stat     !! ERR_NUMERIC from dsyev
        integer :: k
        call la_syev(tensor_matrix(x), w, v, stat)
        if (stat%code /= STATUS_OK) return
        ! each axis with its largest component positive, and det(v) = +1
        do k = 1, 3
            if (v(maxloc(abs(v(:, k)), 1), k) < 0.0_dp) v(:, k) = -v(:, k)
        end do
        if (dot_product(cross(v(:, 1), v(:, 2)), v(:, 3)) < 0.0_dp) v(:, 3) = -v(:, 3)
    end subroutine principal_axes

    !> The ntilde frame of a hang in the body frame: row i is ntilde_i (ntilde_1 = -up,
    !! ntilde_3 = -along, ntilde_2 = ntilde_3 x ntilde_1).
    pure function hang_frame(h) result(r)
        type(hang_t), intent(in) :: h           !! the hang
        real(dp) :: r(3, 3)
        r(1, :) = -h%up
        r(3, :) = -h%along
        r(2, :) = cross(r(3, :), r(1, :))
    end function hang_frame

    !> The hang with the body turned by the small rotation eps (rad, components along
    !! ntilde_1, ntilde_2, ntilde_3 of the hang): the directions fixed in space (up, along)
    !! turn by -eps in the body (Rodrigues' formula, exact for any angle).
    pure function turned_hang(h, eps) result(t)
        type(hang_t), intent(in) :: h           !! the hang
        real(dp), intent(in) :: eps(3)          !! the rotation, rad, in ntilde components
        type(hang_t) :: t
        real(dp) :: r(3, 3), k(3), th
        t = h
        th = norm2(eps)
        if (.not. (th > 0.0_dp)) return
        r = hang_frame(h)
        k = -matmul(eps, r)/th                  ! the axis in body components, turned by -th
        t%up = rotated(h%up)
        t%along = rotated(h%along)
        t%along = t%along - dot_product(t%along, t%up)*t%up
        t%along = t%along/norm2(t%along)
        t%up = t%up/norm2(t%up)
    contains
        pure function rotated(v) result(w)
            real(dp), intent(in) :: v(3)
            real(dp) :: w(3)
            w = v*cos(th) + cross(k, v)*sin(th) + k*dot_product(k, v)*(1.0_dp - cos(th))
        end function rotated
    end function turned_hang

    !> The rig of a hang of the body with mass `mass` and tensor x, under gravity g:
    !! the hang's suspension and mass centre, the principal moments of x and btilde (rows:
    !! the principal axes in the hang's ntilde frame); no damping.
    subroutine hang_rig(mass, g, h, x, rg, stat)
        real(dp), intent(in) :: mass, g         !! the body's mass, gravity (deck units)
        type(hang_t), intent(in) :: h           !! the hang
        real(dp), intent(in) :: x(6)            !! the tensor's entries
        type(rig_t), intent(out) :: rg
        type(status_t), intent(out) :: stat     !! ERR_DECK: not positive definite
        real(dp) :: w(3), v(3, 3)
        call principal_axes(x, w, v, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. (w(1) > 1.0e-12_dp*abs(w(3)) .and. w(1) > 0.0_dp)) then
            call set_error(stat, ERR_DECK, 'the tensor is not positive definite (principal '// &
                'moments '//sci(w(1))//', '//sci(w(2))//', '//sci(w(3))//')')
            return
        end if
        rg%mass = mass
        rg%g = g
        rg%b = h%b
        rg%b_prime = h%b_prime
        rg%l = h%l
        rg%l_prime = h%l_prime
        rg%r = sqrt((0.5_dp*h%b_prime + h%cg_offset)**2 + h%cg_depth**2)
        rg%lambda = atan2(h%cg_depth, 0.5_dp*h%b_prime + h%cg_offset)
        rg%inertia = w
        if (h%cables > 2) then
            ! the platform's body frame: z = up, x = along, y = up x along; its btilde row
            ! i is the axis v(:, i) in (z, x, y) (platform_geometry's platform_inertia)
            rg%cables = h%cables
            rg%cg_offset_y = h%cg_offset_y
            rg%btilde(:, 1) = matmul(h%up, v)
            rg%btilde(:, 2) = matmul(h%along, v)
            rg%btilde(:, 3) = matmul(cross(h%up, h%along), v)
        else
            ! btilde(i, j) = b_i . ntilde_j: row i is the axis v(:, i) in the hang's frame
            rg%btilde = transpose(matmul(hang_frame(h), v))
        end if
        rg%sway_depth = h%cg_depth
        rg%c_v = 0.0_dp
        rg%c_q = 0.0_dp
    end subroutine hang_rig

    !> The attachment points C and D of a hang in the body frame, from the mass centre the
    !! hang's cg_depth and cg_offset place (the origin): C = cg_depth up - (b'/2 +
    !! cg_offset) along, D = C + b' along.
    pure subroutine hang_points(h, c, d)
        type(hang_t), intent(in) :: h           !! the hang
        real(dp), intent(out) :: c(3), d(3)
        c = h%cg_depth*h%up - (0.5_dp*h%b_prime + h%cg_offset)*h%along
        d = c + h%b_prime*h%along
    end subroutine hang_points

    !> The origin of the hang's frame in the body frame, from the mass centre the hang's
    !! cg_depth and cg_offset (and cg_offset_y) place: on two cables the midpoint of CD,
    !! on a platform the centre of its attachment points.
    pure function hang_centre(h) result(o)
        type(hang_t), intent(in) :: h
        real(dp) :: o(3)
        real(dp) :: c(3), d(3)
        if (h%cables > 2) then
            o = h%cg_depth*h%up - h%cg_offset*h%along - h%cg_offset_y*cross(h%up, h%along)
        else
            call hang_points(h, c, d)
            o = 0.5_dp*(c + d)
        end if
    end function hang_centre

    !> A fixture's mass centre (from the origin of hang_points) and inertia in the body
    !! frame for the hang h; origin: the point of the body frame where the table's mass
    !! centre lies (the fixture's cg is given from the body frame's own origin).
    pure subroutine fixture_in_body(h, fix, origin, rf, jf)
        type(hang_t), intent(in) :: h
        type(fixture_t), intent(in) :: fix
        real(dp), intent(in) :: origin(3)
        real(dp), intent(out) :: rf(3), jf(3, 3)
        real(dp) :: r(3, 3)
        if (fix%hang_frame) then
            r(:, 1) = h%along
            r(:, 2) = cross(h%up, h%along)
            r(:, 3) = h%up
            rf = hang_centre(h) + matmul(r, fix%cg)
            jf = matmul(r, matmul(fix%inertia, transpose(r)))
        else
            rf = fix%cg - origin
            jf = fix%inertia
        end if
    end subroutine fixture_in_body

    !> The unit normal of the plane through C, D and the mass centre g (body frame), along x
    !! (g - C) normalised: the direction across the strings.
    pure function plane_normal(h, g) result(n)
        type(hang_t), intent(in) :: h
        real(dp), intent(in) :: g(3)
        real(dp) :: n(3), c(3), d(3)
        call hang_points(h, c, d)
        n = cross(h%along, g - c)
        n = n/max(norm2(n), tiny(1.0_dp))
    end function plane_normal

    !> The hang of what hangs: the body (mass, tensor x about its own mass centre, which lies
    !! dcg from where the table places it) and a fixture.  Their common mass centre G rests
    !! in the vertical plane through C and D: the loaded hang's up is the normal to CD in
    !! the plane of C, D and G (away from G), its cg_depth and cg_offset G's, its along and
    !! rig the table's; mc the mass of both, xc their tensor about G (body frame).
    subroutine loaded_hang(h, mass, x, fix, origin, dcg, hc, mc, xc, stat)
        type(hang_t), intent(in) :: h           !! the hang as the table gives it
        real(dp), intent(in) :: mass, x(6)      !! the body's mass and tensor
        type(fixture_t), intent(in) :: fix      !! the fixture (mass 0: none)
        real(dp), intent(in) :: origin(3)       !! see fixture_in_body
        real(dp), intent(in) :: dcg(3)          !! the body's mass centre from the table's
        type(hang_t), intent(out) :: hc
        real(dp), intent(out) :: mc, xc(6)
        type(status_t), intent(out) :: stat     !! ERR_DECK: G on the line CD
        real(dp) :: c(3), d(3), rf(3), jf(3, 3), g(3), j(3, 3), s, p(3), depth
        stat%code = STATUS_OK
        hc = h
        call hang_points(h, c, d)
        call fixture_in_body(h, fix, origin, rf, jf)
        mc = mass + fix%mass
        g = (mass*dcg + fix%mass*rf)/mc
        j = tensor_matrix(x) + mass*shift(dcg - g) + jf + fix%mass*shift(rf - g)
        xc = tensor_entries(j)
        if (h%cables > 2) then
            ! on a platform the body's up stays the platform's normal: the platform model
            ! finds how it rests with G anywhere
            p = g - hang_centre(h)
            hc%cg_offset = dot_product(p, h%along)
            hc%cg_offset_y = dot_product(p, cross(h%up, h%along))
            hc%cg_depth = -dot_product(p, h%up)
            return
        end if
        s = dot_product(g - c, h%along)
        p = (g - c) - s*h%along
        depth = norm2(p)
        if (.not. (depth > 1.0e-6_dp*h%b_prime)) then
            call set_error(stat, ERR_DECK, 'the mass centre of the body and its fixture '// &
                'lies on the line CD (depth '//sci(depth)//'); allowed: a mass centre that '// &
                'hangs below CD')
            return
        end if
        hc%up = -p/depth
        hc%cg_depth = depth
        hc%cg_offset = s - 0.5_dp*h%b_prime
    contains
        !> The parallel-axis term of a unit mass at r: |r|^2 1 - r r^T.
        pure function shift(r) result(m)
            real(dp), intent(in) :: r(3)
            real(dp) :: m(3, 3)
            integer :: k
            m = -spread(r, 2, 3)*spread(r, 1, 3)
            do k = 1, 3
                m(k, k) = m(k, k) + dot_product(r, r)
            end do
        end function shift
    end subroutine loaded_hang

    !> The rest pose of a rig as a chart state (rates 0): theta_1 = theta_4 = sigma_1 = 0,
    !! sigma_2 where the accelerations at rest vanish, theta_5 from the constraint (see the
    !! module header).  p: the rig's scaled parameters.
    subroutine rest_pose(p, y, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(out) :: y(NSTATE)      !! the rest pose
        type(status_t), intent(out) :: stat     !! ERR_DECK: no rest pose
        type(pendulum_t) :: q
        real(dp) :: s, f, fp, ds, h, qdd(5)
        integer :: it
        y = 0.0_dp
        ! the statics does not depend on the inertia: solve it for an isotropic body, whose
        ! accelerations at rest stay in the plane of the four-bar
        q = p
        q%inertia = sum(p%inertia)/3.0_dp
        q%btilde = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                            1.0_dp], [3, 3])
        q%c_v = 0.0_dp
        q%c_q = 0.0_dp
        s = max(-0.9_dp, min(0.9_dp, 0.5_dp*(p%big_b - 1.0_dp)/p%big_l))
        h = 1.0e-7_dp
        do it = 1, REST_ITER
            call residual(s, f)
            if (stat%code /= STATUS_OK) return
            call residual(s + h, fp)
            if (stat%code /= STATUS_OK) return
            if (.not. (abs(fp - f) > 0.0_dp)) exit
            ds = -f*h/(fp - f)
            ds = max(-0.1_dp, min(0.1_dp, ds))
            s = s + ds
            h = max(1.0e-9_dp, min(1.0e-7_dp, 0.1_dp*abs(ds)))
            if (abs(ds) <= 1.0e-15_dp) exit
        end do
        call residual(s, f)
        if (stat%code /= STATUS_OK) return
        ! the body with its own inertia rests there too
        call chart_accelerations(p, y, qdd, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. (maxval(abs(qdd)) < REST_TOL)) then
            call set_error(stat, ERR_NUMERIC, 'no rest pose found (accelerations '// &
                sci(maxval(abs(qdd)))//' at the best pose); check the rig''s geometry')
        end if
    contains
        !> The chart state at sigma_2 = ss (theta_5 from the constraint in closed form) and the
        !! acceleration of sigma_2 there.
        subroutine residual(ss, ff)
            real(dp), intent(in) :: ss
            real(dp), intent(out) :: ff
            real(dp) :: a, c, k, rr, phi, t1, t2, acc(5)
            ff = 0.0_dp
            if (.not. (abs(ss) < 0.999_dp)) then
                call set_error(stat, ERR_DECK, 'no rest pose: the cable BC would lean to the '// &
                    'horizontal; check l, l_prime, b, b_prime')
                return
            end if
            ! D = (0, a + cos th5, c + sin th5), a = -B + L sigma_2, c = -L zeta: |D| = L'
            a = -p%big_b + p%big_l*ss
            c = -p%big_l*sqrt(1.0_dp - ss**2)
            k = 0.5_dp*(p%big_lp**2 - a**2 - c**2 - 1.0_dp)
            rr = sqrt(a**2 + c**2)
            if (.not. (abs(k) <= rr)) then
                call set_error(stat, ERR_DECK, 'no rest pose: the cables cannot both be taut '// &
                    '(l, l_prime, b, b_prime); allowed: a suspension the body can hang in')
                return
            end if
            phi = atan2(c, a)
            t1 = wrapped(phi + acos(k/rr))
            t2 = wrapped(phi - acos(k/rr))
            y = 0.0_dp
            y(3) = ss
            y(5) = merge(t1, t2, abs(t1) <= abs(t2))
            call chart_accelerations(q, y, acc, stat)
            ff = acc(3)
        end subroutine residual
        pure real(dp) function wrapped(t)
            real(dp), intent(in) :: t
            wrapped = t - 2.0_dp*pi*anint(t/(2.0_dp*pi))
        end function wrapped
    end subroutine rest_pose

    !> The torsion mode of a rig at small amplitude (see the module header): the rest pose,
    !! the linearised equations there, their normal modes, the one with the largest share of
    !! theta_4.
    subroutine torsion_mode(rg, mode, stat)
        type(rig_t), intent(in) :: rg           !! the rig (no damping)
        type(torsion_mode_t), intent(out) :: mode
        type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC
        type(pendulum_t) :: p
        real(dp) :: z(NSTATE, NSTATE), qdd(5), wr(5), wi(5), vr(5, 5), gradg(5), yt(NSTATE)
        real(dp) :: gg, gd, share(5), leak(5), v(5), lam_max
        integer :: j, kc, kt
        call make_pendulum(rg, p, stat)
        if (stat%code /= STATUS_OK) return
        p%stab_rate = 0.0_dp
        p%c_v = 0.0_dp
        p%c_q = 0.0_dp
        call rest_pose(p, mode%y_rest, stat)
        if (stat%code /= STATUS_OK) return
        call chart_jacobian(p, mode%y_rest, qdd, z, stat)
        if (stat%code /= STATUS_OK) return
        call la_eigv(z(6:10, 1:5), wr, wi, vr, stat)
        if (stat%code /= STATUS_OK) return
        ! the constraint's gradient: the direction whose vector leaves it is not a mode
        do j = 1, 5
            yt = mode%y_rest
            yt(6:10) = 0.0_dp
            yt(5 + j) = 1.0_dp
            call chart_constraint(p, yt, gg, gd)
            gradg(j) = gd
        end do
        lam_max = maxval(abs(wr))
        do j = 1, 5
            v = vr(:, j)
            leak(j) = abs(dot_product(gradg, v))/(norm2(gradg)*norm2(v))
            share(j) = (0.5_dp*v(4))**2/(0.25_dp*(v(1)**2 + v(4)**2 + v(5)**2) + &
                                         p%big_l**2*(v(2)**2 + v(3)**2))
        end do
        kc = maxloc(leak, 1)
        share(kc) = -1.0_dp
        do j = 1, 5
            if (j == kc) cycle
            if (abs(wi(j)) > 1.0e-6_dp*lam_max .or. .not. (wr(j) < 0.0_dp)) then
                call set_error(stat, ERR_DECK, 'the body does not hang stably: the linearised '// &
                    'motion at rest has the eigenvalue '//sci(wr(j))//' + '//sci(wi(j))// &
                    ' i; allowed: a hang whose mass centre lies below the line CD')
                return
            end if
        end do
        kt = maxloc(share, 1)
        mode%share = share(kt)
        share(kt) = -1.0_dp
        mode%next_share = maxval(share)
        mode%shape = vr(:, kt)/vr(4, kt)
        mode%omega = sqrt(-wr(kt))
        mode%period = 2.0_dp*pi/mode%omega*sqrt(rg%b_prime/rg%g)
    end subroutine torsion_mode

    !> The period (s) of a hang's rig at peak amplitude amp (degrees of theta_4): the torsion
    !! mode's at amp = 0, else the full model's from a release in the mode's shape (see the
    !! module header), integrated with acc.
    subroutine hang_period(rg, acc, amp, t, stat, pts)
        type(rig_t), intent(in) :: rg           !! the rig (no damping)
        type(accuracy_t), intent(in) :: acc     !! rtol, atol, integrator
        real(dp), intent(in) :: amp             !! degrees, >= 0
        real(dp), intent(out) :: t              !! the period, s
        type(status_t), intent(out) :: stat
        !> a platform given point by point (absent or not given: the regular polygon)
        type(platform_points_t), intent(in), optional :: pts
        type(torsion_mode_t) :: mode
        type(platform_t) :: pl
        real(dp), allocatable :: tm(:), am(:)
        t = 0.0_dp
        if (rg%cables > 2) then
            if (amp <= 0.0_dp) then
                call platform_small_period(rg, t, stat, pts)
            else
                call hang_platform(rg, pl, stat, pts)
                if (stat%code == STATUS_OK) call platform_torsion_period(pl, amp*deg, &
                    acc%rtol, acc%method, t, stat)
                if (stat%code /= STATUS_OK) stat%msg = 'the period at '//fixed(amp, 3)// &
                    ' deg (the platform''s periodic torsion): '//stat%msg
            end if
            return
        end if
        call torsion_mode(rg, mode, stat)
        if (stat%code /= STATUS_OK) return
        if (amp <= 0.0_dp) then
            t = mode%period
            return
        end if
        call run_maxima(rg, acc, mode, amp, 1, tm, am, stat)
        if (stat%code /= STATUS_OK) return
        t = tm(1)*sqrt(rg%b_prime/rg%g)
    end subroutine hang_period

    !> The platform of three cables of a hang's rig (hang_rig: radius b/2, radius_prime
    !! b_prime/2, every cable l; the mass centre at x = r cos(lambda) - b_prime/2, y =
    !! cg_offset_y, depth r sin(lambda); the inertia of platform_inertia), no damping,
    !! checked and at rest (check_platform: ERR_DECK for a rig the cables cannot hold,
    !! ERR_MODEL naming the tipping height).  As platform_measure's platform_of_rig.
    !! Given point by point (pts): the points scaled to the rig's b, b_prime and l
    !! (platform_points_t), the mass centre's x and y from the centroid of the platform's
    !! points, its depth below their mean height.
    subroutine hang_platform(rg, pl, stat, pts)
        type(rig_t), intent(in) :: rg
        type(platform_t), intent(out) :: pl
        type(status_t), intent(out) :: stat
        type(platform_points_t), intent(in), optional :: pts
        real(dp) :: cs(3), cb(3), sup(3, 3), bod(3, 3), off(2)
        integer :: i
        off = [rg%r*cos(rg%lambda) - 0.5_dp*rg%b_prime, rg%cg_offset_y]
        if (present(pts)) then
            if (pts%given) then
                cs = sum(pts%support, dim=2)/3.0_dp
                cb = sum(pts%body, dim=2)/3.0_dp
                do i = 1, 3
                    sup(:, i) = cs + (rg%b/pts%b)*(pts%support(:, i) - cs)
                    bod(:, i) = cb + (rg%b_prime/pts%b_prime)*(pts%body(:, i) - cb)
                end do
                pl = general_platform(3, sup, bod, (rg%l/pts%l)*pts%lengths, rg%mass, &
                                      platform_inertia(rg%inertia, rg%btilde), &
                                      cb(1:2) + off, rg%r*sin(rg%lambda), rg%g)
                pl%c_v = 0.0_dp
                pl%c_q = 0.0_dp
                call check_platform(pl, stat)
                return
            end if
        end if
        pl = regular_platform(rg%cables, 0.5_dp*rg%b, 0.5_dp*rg%b_prime, rg%l, rg%mass, &
                              platform_inertia(rg%inertia, rg%btilde), off, &
                              rg%r*sin(rg%lambda), rg%g)
        pl%c_v = 0.0_dp
        pl%c_q = 0.0_dp
        call check_platform(pl, stat)
    end subroutine hang_platform

    !> The period (s) of the torsion of a platform of three cables (rig rg, hang_rig) at
    !! small amplitude: the platform's equations linearised at its rest pose (module
    !! platform_model's linearise), the mode whose shape has the largest share of the yaw
    !! (the yaw counted by the displacement it causes at radius_prime).
    subroutine platform_small_period(rg, t, stat, pts)
        type(rig_t), intent(in) :: rg           !! the rig (cables = 3)
        real(dp), intent(out) :: t              !! the period, s
        type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_MODEL
        !> a platform given point by point (absent or not given: the regular polygon)
        type(platform_points_t), intent(in), optional :: pts
        type(platform_t) :: pl
        type(platform_modes_t) :: md
        real(dp) :: share, best, wsc(4)
        integer :: j, k, kt
        t = 0.0_dp
        call hang_platform(rg, pl, stat, pts)
        if (stat%code /= STATUS_OK) return
        call linearise(pl, md, stat)
        if (stat%code /= STATUS_OK) return
        do k = 1, md%nf
            wsc(k) = 1.0_dp
            if (pl%free(k) == QPSI) wsc(k) = 0.5_dp*rg%b_prime
            if (pl%free(k) /= QX .and. pl%free(k) /= QY .and. pl%free(k) /= QPSI) &
                wsc(k) = 0.0_dp
        end do
        kt = 0
        best = -1.0_dp
        do j = 1, md%nf
            share = 0.0_dp
            do k = 1, md%nf
                if (pl%free(k) == QPSI) share = (wsc(k)*md%shapes(k, j))**2
            end do
            share = share/max(sum((wsc(1:md%nf)*md%shapes(1:md%nf, j))**2), tiny(1.0_dp))
            if (share > best) then
                best = share
                kt = j
            end if
        end do
        if (.not. (md%omega2(kt) > 0.0_dp)) then
            call set_error(stat, ERR_DECK, 'the body does not rest stably on the platform '// &
                '(omega^2 = '//sci(md%omega2(kt))//' of its torsion); allowed: a mass '// &
                'centre lower on the platform')
            return
        end if
        t = 2.0_dp*pi/sqrt(md%omega2(kt))
    end subroutine platform_small_period

    !> The drift of theta_4's maxima at peak amplitude amp (degrees) over the first `cycles`
    !! cycles after a release in the torsion mode's shape: max_k |(t_k - t_(k-1)) - t_1| / t_1
    !! (t_k the time of the k-th maximum, t_0 = 0), and the largest change of the maxima
    !! themselves over amp (both 0 at amp = 0).
    subroutine maxima_drift(rg, acc, amp, cycles, drift, amp_drift, stat)
        type(rig_t), intent(in) :: rg           !! the rig (no damping)
        type(accuracy_t), intent(in) :: acc     !! rtol, atol, integrator
        real(dp), intent(in) :: amp             !! degrees
        integer, intent(in) :: cycles           !! cycles watched, >= 2
        real(dp), intent(out) :: drift          !! of the intervals, relative
        real(dp), intent(out) :: amp_drift      !! of the maxima, relative
        type(status_t), intent(out) :: stat
        type(torsion_mode_t) :: mode
        real(dp), allocatable :: tm(:), am(:)
        real(dp) :: dk
        integer :: k
        drift = 0.0_dp
        amp_drift = 0.0_dp
        stat%code = STATUS_OK
        ! (a platform's period is its periodic torsion's, the same every cycle)
        if (amp <= 0.0_dp .or. rg%cables > 2) return
        call torsion_mode(rg, mode, stat)
        if (stat%code /= STATUS_OK) return
        call run_maxima(rg, acc, mode, amp, cycles, tm, am, stat)
        if (stat%code /= STATUS_OK) return
        do k = 2, cycles
            dk = tm(k) - tm(k - 1)
            drift = max(drift, abs(dk - tm(1))/tm(1))
        end do
        amp_drift = maxval(abs(am - amp*deg))/(amp*deg)
    end subroutine maxima_drift

    !> Run the full model from a release at rest in the mode's shape at theta_4 = amp
    !! (degrees) to the n-th maximum of theta_4: their times (tau) and values (rad).
    subroutine run_maxima(rg, acc, mode, amp, n, tm, am, stat)
        type(rig_t), intent(in) :: rg
        type(accuracy_t), intent(in) :: acc
        type(torsion_mode_t), intent(in) :: mode
        real(dp), intent(in) :: amp
        integer, intent(in) :: n
        real(dp), allocatable, intent(out) :: tm(:), am(:)
        type(status_t), intent(out) :: stat
        type(pendulum_t) :: p
        type(kane_run_t) :: m
        type(maxima_sink_t) :: sink
        real(dp) :: y0(NSTATE), th(5), thd(5), t_end
        call make_pendulum(rg, p, stat)
        if (stat%code /= STATUS_OK) return
        p%c_v = 0.0_dp
        p%c_q = 0.0_dp
        call mode_start(p, mode, amp*deg, y0, stat)
        if (stat%code /= STATUS_OK) return
        call paper_angles(y0, 0.0_dp, th, thd)
        ! an end well beyond the n-th maximum: twice the small-amplitude periods, and more
        t_end = 2.0_dp*(n + 1)*2.0_dp*pi/mode%omega
        call kane_run_start(m, p, y0, th(3), acc%rtol, acc%atol, acc%method, t_end, &
                            'raise &integration rtol/atol', stat)
        if (stat%code /= STATUS_OK) return
        sink%watch_steps = .true.
        sink%want = n
        allocate (sink%t(n), sink%a(n))
        call drive(m, [0.0_dp, t_end], sink, stat)
        if (stat%code /= STATUS_OK) then
            stat%msg = 'the period at '//fixed(amp, 3)//' deg: '//stat%msg
            return
        end if
        if (sink%found < n) then
            call set_error(stat, ERR_NUMERIC, 'the period at '//fixed(amp, 3)//' deg: '// &
                'theta4 reached no maximum after its swing within tau = '//fixed(t_end, 3)// &
                '; the body does not swing in torsion in this hang')
            return
        end if
        tm = sink%t
        am = sink%a
    end subroutine run_maxima

    !> The release at rest in the mode's shape at theta_4 = a (rad): the rest pose plus
    !! (a/shape_4) shape, theta_5 then from the constraint (Newton's method).
    subroutine mode_start(p, mode, a, y0, stat)
        type(pendulum_t), intent(in) :: p
        type(torsion_mode_t), intent(in) :: mode
        real(dp), intent(in) :: a
        real(dp), intent(out) :: y0(NSTATE)
        type(status_t), intent(out) :: stat
        real(dp) :: yt(NSTATE), gg, gd
        integer :: it
        stat%code = STATUS_OK
        y0 = mode%y_rest
        y0(1:5) = y0(1:5) + a*mode%shape
        y0(6:10) = 0.0_dp
        do it = 1, 40
            yt = y0
            yt(10) = 1.0_dp
            call chart_constraint(p, yt, gg, gd)
            if (.not. (abs(gd) > 0.0_dp)) exit
            y0(5) = y0(5) - gg/gd
            if (abs(gg) <= 1.0e-15_dp*max(1.0_dp, p%big_lp**2)) exit
        end do
        call chart_constraint(p, y0, gg, gd)
        if (.not. (abs(gg) <= 1.0e-12_dp*max(1.0_dp, p%big_lp**2)) .or. &
            .not. (y0(2)**2 + y0(3)**2 < 0.99_dp)) then
            call set_error(stat, ERR_DECK, 'no release at '//fixed(a/deg, 3)//' deg: the '// &
                'cables cannot both be taut there; allowed: a smaller amplitude')
        end if
    end subroutine mode_start

end module hang_model
