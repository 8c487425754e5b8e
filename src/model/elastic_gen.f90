!> The elastic-cable model in generalized coordinates with the cable stretches as states.
!!
!! Why.  In the maximal coordinates of elastic_model (R*, v*, quaternion, omega) a stiff
!! cable pulls along its own direction u, and u turns with the swing.  An implicit method
!! linearises the stiff force once per step (simplified Newton with one Jacobian); over a
!! step the direction turns by phi = h w_b (w_b the swing rate), and the frozen Jacobian
!! then mistakes the swing for a stretch of L phi^2/2, a force error k L phi^2/2: the
!! Newton contraction is about k h (h w_b)^2, so the step is held to h ~ (k w_b^2)^(-1/3)
!! whatever the tolerance (the step counts it costs: doc/elastic.md).  And
!! the error test sees the stiff stretching velocity and the slow swing velocity in the
!! same components v*, omega, so it can only treat both alike.  In coordinates where each
!! stretch s_j = |cable j| - L0_j is a coordinate, the spring energy is (k/2L0) s_j^2
!! exactly, its Hessian is constant, the frozen Jacobian is right for the stiff part, and
!! the stretches and their rates are state components of their own.
!!
!! The coordinates q = (sigma1, sigma2, phi, psi, s1, s2), the state y = (q, q') (12):
!!   C = B + (L01 + s1) e,  e = (sigma1, sigma2, -(1 - sigma1^2 - sigma2^2)^(1/2)), the
!!       direction of the cable BC by its horizontal components (the regular chart of
!!       bifilar_model);
!!   D lies on the circle |D - A| = L02 + s2 = l2, |D - C| = 1 (b'): with a = C/|C| (A is
!!       the origin), D = a_d a + r (cos phi p + sin phi (a x p)), a_d = (l2^2 - 1 + |C|^2)/
!!       (2 |C|), r = (l2^2 - a_d^2)^(1/2), p the unit component of B - A normal to a;
!!   the body frame: ntilde3 = C - D; ntilde1 = sin psi u + cos psi w with w the unit
!!       component of -n3 normal to ntilde3 and u = w x (D - C): psi is the paper's theta1
!!       (elastic_chart), the turn of the body about CD;
!!   R* = C + r (sin lambda ntilde1 - cos lambda ntilde3) (eqs. (21)-(22)).
!! The chart is regular while the cable BC is not horizontal, D is off the line AC, AC is
!! not along AB and CD is not vertical (chart_quality); elastic_solver falls back to the
!! maximal coordinates where it is not.
!!
!! The equations of motion are elastic_model's, unchanged: the pose and velocities (R*,
!! v*, R, omega) are built from (q, q'), elastic_rhs gives the accelerations (a*, alpha),
!! and with J = d(v*, omega)/dq' (the pose map's Jacobian, 6 x 6) and the accelerations
!! (a0, alpha0) of the pose along q' at q'' = 0,
!!   q'' = J^-1 ((a*, alpha) - (a0, alpha0)).
!! Pose, J and (a0, alpha0) come from second-order forward derivatives ("jets": value,
!! first and second derivative along a direction) of the construction above.
module elastic_gen
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_NUMERIC, STATUS_OK, GEN_ERR_CHART
    use ode_system, only: ode_system_t
    use lapack_wrap, only: la_solve
    use vectors, only: cross
    use elastic_model, only: elastic_t, natural_lengths, matrix_to_quat, elastic_pose, &
                             elastic_rhs_stretched, ELASTIC_NSTATE
    use unused_arg, only: unused
    implicit none
    private

    !> y = (sigma1, sigma2, phi, psi, s1, s2) and their rates
    integer, parameter, public :: GEN_NSTATE = 12
    !> Indices of the stretches s1 (BC), s2 (AD) and their rates in the state.
    integer, parameter, public :: GEN_S1 = 5, GEN_S2 = 6, GEN_S1_RATE = 11, GEN_S2_RATE = 12
    !> Jets: value (0), first derivatives along q_1..q_6 (1:6) and along q' (7), second
    !! derivative along q' (8).
    integer, parameter :: NJ = 8

    !> The elastic model in the coordinates above (el: the model, its parameters and modes).
    type, extends(ode_system_t), public :: elastic_gen_t
        type(elastic_t) :: el
    contains
        procedure :: rhs => gen_rhs
    end type elastic_gen_t

    public :: gen_to_maximal, maximal_to_gen, chart_quality

contains

    ! ------------------------------------------------------------------------------------
    ! Jets: a quantity with its first derivatives along the six coordinates (1:6), along
    ! the rates q' (7), and its second derivative along q' at q'' = 0 (8)
    ! ------------------------------------------------------------------------------------

    pure function jmul(a, b) result(c)
        real(dp), intent(in) :: a(0:NJ), b(0:NJ)
        real(dp) :: c(0:NJ)
        c(0) = a(0)*b(0)
        c(1:7) = a(1:7)*b(0) + a(0)*b(1:7)
        c(8) = a(8)*b(0) + 2.0_dp*a(7)*b(7) + a(0)*b(8)
    end function jmul

    pure function jinv(a) result(c)
        real(dp), intent(in) :: a(0:NJ)
        real(dp) :: c(0:NJ)
        c(0) = 1.0_dp/a(0)
        c(1:7) = -a(1:7)*c(0)**2
        c(8) = -a(8)*c(0)**2 + 2.0_dp*a(7)**2*c(0)**3
    end function jinv

    pure function jsqrt(a) result(c)
        real(dp), intent(in) :: a(0:NJ)
        real(dp) :: c(0:NJ)
        c(0) = sqrt(a(0))
        c(1:7) = a(1:7)/(2.0_dp*c(0))
        c(8) = (a(8) - 2.0_dp*c(7)**2)/(2.0_dp*c(0))
    end function jsqrt

    !> sin and cos of a jet.
    pure subroutine jsincos(a, sn, cs)
        real(dp), intent(in) :: a(0:NJ)
        real(dp), intent(out) :: sn(0:NJ), cs(0:NJ)
        real(dp) :: s0, c0
        s0 = sin(a(0))
        c0 = cos(a(0))
        sn(0) = s0
        sn(1:7) = c0*a(1:7)
        sn(8) = -s0*a(7)**2 + c0*a(8)
        cs(0) = c0
        cs(1:7) = -s0*a(1:7)
        cs(8) = -c0*a(7)**2 - s0*a(8)
    end subroutine jsincos

    pure function vdot(u, v) result(c)
        real(dp), intent(in) :: u(3, 0:NJ), v(3, 0:NJ)
        real(dp) :: c(0:NJ)
        c = jmul(u(1, :), v(1, :)) + jmul(u(2, :), v(2, :)) + jmul(u(3, :), v(3, :))
    end function vdot

    pure function vcross(u, v) result(c)
        real(dp), intent(in) :: u(3, 0:NJ), v(3, 0:NJ)
        real(dp) :: c(3, 0:NJ)
        c(1, :) = jmul(u(2, :), v(3, :)) - jmul(u(3, :), v(2, :))
        c(2, :) = jmul(u(3, :), v(1, :)) - jmul(u(1, :), v(3, :))
        c(3, :) = jmul(u(1, :), v(2, :)) - jmul(u(2, :), v(1, :))
    end function vcross

    pure function vscale(a, v) result(c)
        real(dp), intent(in) :: a(0:NJ), v(3, 0:NJ)
        real(dp) :: c(3, 0:NJ)
        integer :: i
        do i = 1, 3
            c(i, :) = jmul(a, v(i, :))
        end do
    end function vscale

    pure function vunit(v) result(c)
        real(dp), intent(in) :: v(3, 0:NJ)
        real(dp) :: c(3, 0:NJ)
        c = vscale(jinv(jsqrt(vdot(v, v))), v)
    end function vunit

    !> A constant vector as a jet.
    pure function vconst(x) result(c)
        real(dp), intent(in) :: x(3)
        real(dp) :: c(3, 0:NJ)
        c = 0.0_dp
        c(:, 0) = x
    end function vconst

    ! ------------------------------------------------------------------------------------
    ! The pose map
    ! ------------------------------------------------------------------------------------

    !> Jets of the pose at q with rates qd: R*, C, D and the body frame (fr(:, i, :) =
    !! ntilde_i in n components), and the chart's measure of regularity (the smallest of
    !! cos(BC from the vertical), r/l2, |p|/|B - A| and cos theta5).
    pure subroutine pose_jets(el, q, qd, rs, c, d, fr, quality)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: q(6), qd(6)
        real(dp), intent(out) :: rs(3, 0:NJ), c(3, 0:NJ), d(3, 0:NJ), fr(3, 3, 0:NJ)
        real(dp), intent(out) :: quality
        real(dp) :: x(6, 0:NJ), l0(2), l1(0:NJ), l2(0:NJ), ez(0:NJ), e(3, 0:NJ), cc(0:NJ)
        real(dp) :: dc(0:NJ), a(3, 0:NJ), ad(0:NJ), rc(0:NJ), bv(3, 0:NJ), pr(3, 0:NJ)
        real(dp) :: p(3, 0:NJ), qv(3, 0:NJ), dd(3, 0:NJ), wr(3, 0:NJ), w(3, 0:NJ), u(3, 0:NJ)
        real(dp) :: sp(0:NJ), cp(0:NJ), sl, cl, one(0:NJ)
        integer :: i
        l0 = natural_lengths(el)
        x = 0.0_dp
        do i = 1, 6
            x(i, 0) = q(i)
            x(i, i) = 1.0_dp
            x(i, 7) = qd(i)
        end do
        one = 0.0_dp
        one(0) = 1.0_dp
        l1 = x(5, :)
        l1(0) = l1(0) + l0(1)
        l2 = x(6, :)
        l2(0) = l2(0) + l0(2)
        ! C = B + l1 e
        ez = -jsqrt(one - jmul(x(1, :), x(1, :)) - jmul(x(2, :), x(2, :)))
        e(1, :) = x(1, :)
        e(2, :) = x(2, :)
        e(3, :) = ez
        c = vscale(l1, e)
        c(2, 0) = c(2, 0) - el%p%big_b
        ! D on the circle about the line AC
        cc = vdot(c, c)
        dc = jsqrt(cc)
        a = vscale(jinv(dc), c)
        ad = jmul(jmul(l2, l2) - one + cc, jinv(2.0_dp*dc))
        rc = jsqrt(jmul(l2, l2) - jmul(ad, ad))
        bv = vconst([0.0_dp, -el%p%big_b, 0.0_dp])
        pr = bv - vscale(vdot(bv, a), a)
        p = vunit(pr)
        qv = vcross(a, p)
        call jsincos(x(3, :), sp, cp)
        d = vscale(ad, a) + vscale(rc, vscale(cp, p) + vscale(sp, qv))
        ! the body frame
        dd = d - c
        wr = vscale(dd(3, :), dd)
        wr(3, 0) = wr(3, 0) - 1.0_dp
        w = vunit(wr)
        u = vcross(w, dd)
        call jsincos(x(4, :), sp, cp)
        fr(:, 1, :) = vscale(sp, u) + vscale(cp, w)
        fr(:, 3, :) = -dd
        fr(:, 2, :) = vcross(fr(:, 3, :), fr(:, 1, :))
        sl = el%p%r*sin(el%p%lambda)
        cl = el%p%r*cos(el%p%lambda)
        rs = c + sl*fr(:, 1, :) - cl*fr(:, 3, :)
        quality = min(-ez(0), rc(0)/l2(0), sqrt(dot_product(pr(:, 0), pr(:, 0)))/el%p%big_b, &
                      sqrt(dot_product(wr(:, 0), wr(:, 0))))
    end subroutine pose_jets

    !> From the pose jets: J = d(v*, omega)/dq' (6 x 6, omega = 1/2 sum ntilde_i x
    !! ntilde_i' in n components), the velocities (v*, omega) and the accelerations (a0,
    !! alpha0) of the pose along q' at q'' = 0 (alpha0 = 1/2 sum ntilde_i x ntilde_i'').
    pure subroutine pose_rates(rs, fr, jm, vel, acc0)
        real(dp), intent(in) :: rs(3, 0:NJ), fr(3, 3, 0:NJ)
        real(dp), intent(out) :: jm(6, 6), vel(6), acc0(6)
        real(dp) :: om(3, 8)
        integer :: i, k
        om = 0.0_dp
        do i = 1, 3
            do k = 1, 8
                om(:, k) = om(:, k) + 0.5_dp*cross(fr(:, i, 0), fr(:, i, k))
            end do
        end do
        jm(1:3, :) = rs(:, 1:6)
        jm(4:6, :) = om(:, 1:6)
        vel(1:3) = rs(:, 7)
        vel(4:6) = om(:, 7)
        acc0(1:3) = rs(:, 8)
        acc0(4:6) = om(:, 8)
    end subroutine pose_rates

    ! ------------------------------------------------------------------------------------
    ! Conversions and the right-hand side
    ! ------------------------------------------------------------------------------------

    !> The maximal state (elastic_model: R*, v*, quaternion, omega in body components) of a
    !! generalized state, and the chart's regularity measure there (optional).
    function gen_to_maximal(el, yg, quality) result(y)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: yg(:)           !! generalized state (12)
        real(dp), intent(out), optional :: quality
        real(dp) :: y(ELASTIC_NSTATE)
        real(dp) :: rs(3, 0:NJ), c(3, 0:NJ), d(3, 0:NJ), fr(3, 3, 0:NJ), jm(6, 6), vel(6)
        real(dp) :: acc0(6), qual, r(3, 3)
        call pose_jets(el, yg(1:6), yg(7:12), rs, c, d, fr, qual)
        call pose_rates(rs, fr, jm, vel, acc0)
        r = fr(:, :, 0)                         ! R(:, i) = ntilde_i
        y(1:3) = rs(:, 0)
        y(4:6) = vel(1:3)
        y(7:10) = matrix_to_quat(r)
        y(11:13) = matmul(vel(4:6), r)          ! R^T omega
        if (present(quality)) quality = qual
    end function gen_to_maximal

    !> The generalized state of a maximal one: s_j = |cable j| - L0_j, sigma the horizontal
    !! components of the direction of BC, phi the position of D on its circle, psi the turn
    !! about CD (phi, psi continued to the 2 pi branch nearest ref(3:4) when given); the
    !! rates q' = J^-1 (v*, omega).  stat: ERR_NUMERIC when the chart is singular there.
    subroutine maximal_to_gen(el, y, yg, stat, ref)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)            !! maximal state (13)
        real(dp), intent(out) :: yg(GEN_NSTATE)
        type(status_t), intent(out) :: stat
        real(dp), intent(in), optional :: ref(:)    !! a nearby generalized state (branches)
        real(dp) :: c(3), d(3), n(3, 3), l0(2), a(3), ad, b(3), p(3), w(3), u(3), qual
        real(dp) :: jm(6, 6), rhs(6), r(3, 3), phi, psi, rs(3, 0:NJ), cj(3, 0:NJ), dj(3, 0:NJ)
        real(dp) :: fr(3, 3, 0:NJ), vel(6), acc0(6)
        stat%code = STATUS_OK
        yg = 0.0_dp
        call chart_geometry(el, y, c, d, n, a, ad, p, w, qual)
        l0 = natural_lengths(el)
        b = [0.0_dp, -el%p%big_b, 0.0_dp]
        p = p/norm2(p)
        phi = atan2(dot_product(d - ad*a, cross(a, p)), dot_product(d - ad*a, p))
        w = w/norm2(w)
        u = cross(w, d - c)
        psi = atan2(dot_product(n(1, :), u), dot_product(n(1, :), w))
        if (present(ref)) then
            phi = phi + 2.0_dp*pi*anint((ref(3) - phi)/(2.0_dp*pi))
            psi = psi + 2.0_dp*pi*anint((ref(4) - psi)/(2.0_dp*pi))
        end if
        yg(1:6) = [(c(1:2) - b(1:2))/norm2(c - b), phi, psi, norm2(c - b) - l0(1), &
                   norm2(d) - l0(2)]
        call pose_jets(el, yg(1:6), [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], rs, cj, &
                       dj, fr, qual)
        call pose_rates(rs, fr, jm, vel, acc0)
        r = transpose(n)
        rhs(1:3) = y(4:6)
        rhs(4:6) = matmul(r, y(11:13))          ! omega in n components
        call la_solve(jm, rhs, stat)
        if (stat%code /= STATUS_OK) then
            call set_error(stat, ERR_NUMERIC, 'elastic model: the generalized coordinates '// &
                'are singular at this pose')
            return
        end if
        yg(7:12) = rhs
    end subroutine maximal_to_gen

    !> The regularity measure of the chart at a maximal state (see pose_jets; 1 at best,
    !! 0 at a singularity).
    function chart_quality(el, y) result(qual)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)            !! maximal state (13)
        real(dp) :: qual
        real(dp) :: c(3), d(3), n(3, 3), a(3), ad, p(3), w(3)
        call chart_geometry(el, y, c, d, n, a, ad, p, w, qual)
    end function chart_quality

    !> The chart's construction at the pose of a maximal state: C, D and the frame
    !! (n(i, :) = ntilde_i), the axis a = C/|C| of D's circle and the distance a_d of its
    !! centre from A, p and w before normalisation (the component of B - A normal to a, of
    !! -n3 normal to CD), and the regularity measure as in pose_jets.
    pure subroutine chart_geometry(el, y, c, d, n, a, ad, p, w, qual)
        type(elastic_t), intent(in) :: el
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: c(3), d(3), n(3, 3), a(3), ad, p(3), w(3), qual
        real(dp) :: e(3), vc(3), vd(3), omega(3), b(3), l2, dc, dd(3)
        call elastic_pose(el%p, y, c, d, e, vc, vd, n, omega)
        b = [0.0_dp, -el%p%big_b, 0.0_dp]
        l2 = norm2(d)
        dc = norm2(c)
        a = c/dc
        ad = (l2**2 - 1.0_dp + dc**2)/(2.0_dp*dc)
        p = b - dot_product(b, a)*a
        dd = d - c
        w = [0.0_dp, 0.0_dp, -1.0_dp] + dd(3)*dd
        qual = min((b(3) - c(3))/norm2(c - b), sqrt(max(0.0_dp, l2**2 - ad**2))/l2, &
                   norm2(p)/el%p%big_b, norm2(w))
    end subroutine chart_geometry

    !> Right-hand side in the generalized coordinates: q'' = J^-1 ((a*, alpha) - (a0,
    !! alpha0)) with (a*, alpha) from elastic_model's equations at the same pose and
    !! velocities.  stat: the model's, or ERR_NUMERIC where the chart is singular.
    subroutine gen_rhs(sys, t, y, ydot, stat)
        class(elastic_gen_t), intent(inout) :: sys
        real(dp), intent(in) :: t               !! tau (the system is autonomous)
        real(dp), intent(in) :: y(:)            !! generalized state (12)
        real(dp), intent(out) :: ydot(:)        !! its derivative
        type(status_t), intent(out) :: stat
        real(dp) :: rs(3, 0:NJ), c(3, 0:NJ), d(3, 0:NJ), fr(3, 3, 0:NJ), vel(6), acc0(6), qual
        real(dp) :: r(3, 3), ym(ELASTIC_NSTATE), fm(ELASTIC_NSTATE), jm(6, 6), acc(6)
        call unused(t)
        ydot = 0.0_dp
        call pose_jets(sys%el, y(1:6), y(7:12), rs, c, d, fr, qual)
        if (.not. (qual > 0.0_dp)) then
            call set_error(stat, GEN_ERR_CHART, 'elastic model: the generalized coordinates '// &
                'are singular at this pose')
            return
        end if
        call pose_rates(rs, fr, jm, vel, acc0)
        r = fr(:, :, 0)
        ym(1:3) = rs(:, 0)
        ym(4:6) = vel(1:3)
        ym(7:10) = matrix_to_quat(r)
        ym(11:13) = matmul(vel(4:6), r)
        call elastic_rhs_stretched(sys%el, ym, reshape([y(5), y(11), y(6), y(12)], [2, 2]), &
                                   fm, stat)
        if (stat%code /= STATUS_OK) return
        acc(1:3) = fm(4:6) - acc0(1:3)
        acc(4:6) = matmul(r, fm(11:13)) - acc0(4:6)
        call la_solve(jm, acc, stat)
        if (stat%code /= STATUS_OK) then
            call set_error(stat, GEN_ERR_CHART, 'elastic model: the generalized coordinates '// &
                'are singular at this pose')
            return
        end if
        ydot(1:6) = y(7:12)
        ydot(7:12) = acc
    end subroutine gen_rhs

end module elastic_gen
