!> The checks of the rig's groups (submodule of rig_groups): each value finite and in its
!! range, words known, the first problem an ERR_DECK status naming the group, the variable,
!! its value, what is wrong and what is allowed.  A check never changes a value: where the
!! run takes a value other than the one given (a platform's b = 2 radius, the mass centre's
!! r and lambda from cg_depth and cg_offset, a word in lower case), it checks that value,
!! made by the group's normalisation on a copy.  Each returns at once when an earlier check
!! failed.
submodule (rig_groups) rig_checks
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: sci
    use value_checks, only: bad, finite, positive, dimensional, over_b_prime, angle, &
        check_word, RATIO_MIN, RTOL_MIN, DIM_MAX
    use platform_geometry, only: platform_t, general_platform, platform_prepare
    implicit none

    !> Largest damping coefficient in the scaled units of the model (c_v over
    !! m b' sqrt(g b'), c_q over m b'^2; critical damping of torsion is of order 1).
    real(dp), parameter :: DAMPING_SCALED_MAX = 1.0e3_dp
    real(dp), parameter :: ATOL_MIN = 1.0e-30_dp        !! smallest absolute tolerance
    real(dp), parameter :: ATOL_MAX = 1.0_dp            !! largest absolute tolerance
    real(dp), parameter :: MAX_ROWS = 1.0e5_dp          !! largest tau_end/dtau_out
    !> Each principal moment over m b'^2 in INERTIA_MIN .. INERTIA_MAX.
    real(dp), parameter :: INERTIA_MIN = 1.0e-6_dp, INERTIA_MAX = 1.0e6_dp
    !> Largest |theta_dot| (rad per unit tau); the natural frequencies are of order 1.
    real(dp), parameter :: RATE_MAX = 1.0e3_dp
    real(dp), parameter :: STIFFNESS_MIN = 1.0_dp       !! &cables stiffness range
    real(dp), parameter :: STIFFNESS_MAX = 1.0e12_dp
    real(dp), parameter :: DAMPING_MAX = 10.0_dp        !! largest &cables damping ratio
    real(dp), parameter :: ORTHO_TOL = 1.0e-9_dp        !! orthonormality of btilde
    real(dp), parameter :: TRIANGLE_SLACK = 1.0e-12_dp  !! relative slack of I1 <= I2 + I3

contains

    !> &suspension: all lengths and g finite, > 0 and within DIM_MIN .. DIM_MAX; b, l, l'
    !! over b' within RATIO_MIN .. RATIO_MAX.
    module procedure check_suspension
        type(suspension_group_t) :: s
        if (stat%code /= STATUS_OK) return
        if (self%cables < 2 .or. self%cables > MAX_CABLES) then
            call bad(stat, 'suspension', 'cables', itoa(self%cables), 'number of cables '// &
                     'out of range', '2 (a bifilar) .. '//itoa(MAX_CABLES)//' (a platform on '// &
                     'that many cables at radius and radius_prime)')
            return
        end if
        if (self%cables == 2) then
            if (self%pointwise()) then
                call bad(stat, 'suspension', trim(merge('support_points', 'body_points   ', &
                         self%gave('support_points'))), 'given', 'a platform''s points with '// &
                         'cables = 2', 'b, b_prime, l, l_prime for a bifilar; '// &
                         'support_points, body_points, lengths with cables >= 3')
                return
            end if
            if (self%gave('radius') .or. self%gave('radius_prime')) then
                call bad(stat, 'suspension', trim(merge('radius      ', 'radius_prime', &
                         self%gave('radius'))), rshort(merge(self%radius, self%radius_prime, &
                         self%gave('radius'))), 'a platform''s radius with cables = 2', &
                         'b and b_prime (the full distances between the two cables) for a '// &
                         'bifilar; radius and radius_prime with cables >= 3')
                return
            end if
        else
            ! a platform: its cables at one radius; the equivalent pair b = 2 R, b' = 2 R'
            if (self%gave('b') .or. self%gave('b_prime')) then
                call bad(stat, 'suspension', trim(merge('b      ', 'b_prime', self%gave(&
                         'b'))), rshort(merge(self%b, self%b_prime, self%gave('b'))), &
                         'a bifilar''s spacing with cables = '//itoa(self%cables), 'radius and '// &
                         'radius_prime (the radii of the attachment circles on the support and '// &
                         'the body) with cables >= 3')
                return
            end if
            if (self%pointwise()) then
                call check_points(self, stat)
                if (stat%code /= STATUS_OK) return
            else
                call positive(stat, 'suspension', 'radius', self%radius, 'radius > 0 with '// &
                              'cables >= 3 (or the platform point by point: support_points, '// &
                              'body_points, lengths)')
                call positive(stat, 'suspension', 'radius_prime', self%radius_prime, &
                              'radius_prime > 0 with cables >= 3')
                if (stat%code /= STATUS_OK) return
                if (self%gave('l_prime') .and. self%l_prime /= self%l) then
                    call bad(stat, 'suspension', 'l_prime', rshort(self%l_prime), 'differs '// &
                             'from l = '//rshort(self%l)//' on a platform of '// &
                             itoa(self%cables)//' cables', 'every cable of length l (leave '// &
                             'l_prime out) with cables >= 3, or lengths(1:'// &
                             itoa(self%cables)//') with the platform point by point')
                    return
                end if
            end if
        end if
        ! the lengths as the run takes them (a platform's equivalent pair: normalise)
        s = self
        call s%normalise()
        call positive(stat, 'suspension', 'b', s%b, 'lengths > 0')
        call positive(stat, 'suspension', 'b_prime', s%b_prime, 'lengths > 0')
        call positive(stat, 'suspension', 'l', s%l, 'lengths > 0')
        call positive(stat, 'suspension', 'l_prime', s%l_prime, 'lengths > 0')
        call positive(stat, 'suspension', 'g', s%g, 'g > 0')
        call dimensional(stat, 'suspension', 'b_prime', s%b_prime)
        call dimensional(stat, 'suspension', 'b', s%b)
        call dimensional(stat, 'suspension', 'l', s%l)
        call dimensional(stat, 'suspension', 'l_prime', s%l_prime)
        call dimensional(stat, 'suspension', 'g', s%g)
        call over_b_prime(stat, 'suspension', 'b', s%b, s%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'suspension', 'l', s%l, s%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'suspension', 'l_prime', s%l_prime, s%b_prime, RATIO_MIN)
        if (stat%code /= STATUS_OK .or. self%cables <= 2 .or. self%pointwise()) return
        ! a regular platform: the cables reach down from the support's circle to the body's
        if (.not. (self%l > abs(self%radius - self%radius_prime))) then
            call bad(stat, 'suspension', 'l', rshort(self%l), 'not longer than |radius - '// &
                     'radius_prime| = '//rshort(abs(self%radius - self%radius_prime))// &
                     ': the cables cannot reach the body below the support', &
                     'l > |radius - radius_prime|')
        end if
    end procedure check_suspension

    !> A platform given point by point: support_points(:, 1:n), body_points(:, 1:n) and
    !! lengths(1:n) given whole and finite, nothing beyond n, not mixed with the regular
    !! polygon's radius, radius_prime, l; lengths > 0 in range; then the geometry as the
    !! model takes it (platform_prepare: the points distinct, not collinear, every cable
    !! able to reach below the supports), its message under &suspension.
    subroutine check_points(self, stat)
        class(suspension_group_t), intent(in) :: self
        type(status_t), intent(inout) :: stat
        type(platform_t) :: pl
        type(status_t) :: st
        real(dp) :: jb(3, 3)
        integer :: n, i, k
        character(len=*), parameter :: EITHER = 'a platform either as a regular polygon '// &
            '(radius, radius_prime, l) or point by point (support_points, body_points, lengths)'
        n = self%cables
        if (self%gave('radius') .or. self%gave('radius_prime') .or. self%gave('l') .or. &
            self%gave('l_prime')) then
            call bad(stat, 'suspension', trim(merge('radius      ', 'l           ', &
                     self%gave('radius') .or. self%gave('radius_prime'))), 'given', &
                     'with support_points, body_points, lengths', EITHER)
            return
        end if
        call whole('support_points', self%support_points)
        call whole('body_points', self%body_points)
        if (stat%code /= STATUS_OK) return
        if (.not. self%gave('lengths') .or. any(self%lengths(1:n) == NOT_GIVEN)) then
            call bad(stat, 'suspension', 'lengths', 'not given for every cable', &
                     'the length of each of the '//itoa(n)//' cables', 'lengths(1:'// &
                     itoa(n)//'), every one > 0')
            return
        end if
        if (any(self%lengths(n + 1:) /= NOT_GIVEN)) then
            call bad(stat, 'suspension', 'lengths', rlist_short(self%lengths(1:n + 1)), &
                     'more lengths than cables = '//itoa(n), 'lengths(1:'//itoa(n)//')')
            return
        end if
        do i = 1, n
            call positive(stat, 'suspension', 'lengths('//itoa(i)//')', self%lengths(i), &
                          'every length > 0')
            call dimensional(stat, 'suspension', 'lengths('//itoa(i)//')', self%lengths(i))
        end do
        if (stat%code /= STATUS_OK) return
        jb = 0.0_dp
        do k = 1, 3
            jb(k, k) = 1.0_dp
        end do
        pl = general_platform(n, self%support_points(:, 1:n), self%body_points(:, 1:n), &
                              self%lengths(1:n), 1.0_dp, jb, [0.0_dp, 0.0_dp], 0.0_dp, 1.0_dp)
        call platform_prepare(pl, st)
        if (st%code == STATUS_OK) return
        if (index(st%msg, 'platform: ') == 1) then
            call set_error(stat, ERR_DECK, '&suspension: '//st%msg(11:))
        else if (index(st%msg, 'platform ') == 1) then
            call set_error(stat, ERR_DECK, '&suspension '//st%msg(10:))
        else
            call set_error(stat, ERR_DECK, '&suspension: '//st%msg)
        end if
    contains
        !> points(:, 1:n) given and finite, within DIM_MAX; no column beyond n.
        subroutine whole(var, pts)
            character(len=*), intent(in) :: var
            real(dp), intent(in) :: pts(:, :)
            integer :: j, c
            if (stat%code /= STATUS_OK) return
            if (.not. self%gave(var)) then
                call bad(stat, 'suspension', var, 'not given', 'a platform point by '// &
                         'point needs support_points, body_points and lengths', EITHER)
                return
            end if
            do j = 1, n
                if (any(pts(:, j) == NOT_GIVEN)) then
                    call bad(stat, 'suspension', var//'(:,'//itoa(j)//')', 'not given '// &
                             'whole', 'each of the '//itoa(n)//' cables needs its point''s '// &
                             'three coordinates', var//'(:, 1:'//itoa(n)//') = x, y, z of '// &
                             'each point')
                    return
                end if
                do c = 1, 3
                    call finite(stat, 'suspension', var//'('//itoa(c)//','//itoa(j)//')', &
                                pts(c, j))
                end do
                if (stat%code /= STATUS_OK) return
                if (maxval(abs(pts(:, j))) > DIM_MAX) then
                    call bad(stat, 'suspension', var//'(:,'//itoa(j)//')', &
                             rlist_short(pts(:, j)), 'out of range', '|coordinate| <= '// &
                             rshort(DIM_MAX)//' in any units')
                    return
                end if
            end do
            do j = n + 1, size(pts, 2)
                if (any(pts(:, j) /= NOT_GIVEN)) then
                    call bad(stat, 'suspension', var//'(:,'//itoa(j)//')', &
                             'given', 'a point beyond cables = '//itoa(n), var// &
                             '(:, 1:'//itoa(n)//')')
                    return
                end if
            end do
        end subroutine whole
    end subroutine check_points

    !> &body: mass > 0; principal moments > 0 obeying the triangle inequalities; r >= 0;
    !! btilde a right-handed orthonormal matrix; everything finite.
    module procedure check_body
        real(dp) :: t(3), half(3), slack, mmt(3,3), det, err, lr, r, lambda
        integer :: i, j, iw, jw
        character(len=*), parameter :: TRI_NAMES(3) = ['I1', 'I2', 'I3']
        if (stat%code /= STATUS_OK) return
        call positive(stat, 'body', 'mass', self%mass, 'mass > 0')
        do i = 1, 3
            call finite(stat, 'body', 'inertia', self%inertia(i))
        end do
        if (stat%code /= STATUS_OK) return
        if (any(self%inertia <= 0.0_dp)) then
            call bad(stat, 'body', 'inertia', rlist_short(self%inertia), &
                     'a principal moment of inertia is <= 0', 'all three > 0')
            return
        end if
        call dimensional(stat, 'body', 'mass', self%mass)
        do i = 1, 3
            call dimensional(stat, 'body', 'inertia', self%inertia(i))
        end do
        if (stat%code /= STATUS_OK) return
        if (self%gave('size')) then
            call positive(stat, 'body', 'size', self%size, 'size > 0 (the diameter of a '// &
                          'sphere that holds the body, deck length units)')
            if (stat%code == STATUS_OK) call dimensional(stat, 'body', 'size', self%size)
            if (stat%code /= STATUS_OK) return
        end if
        ! I/(m b'^2) in logarithms: the quotient itself may overflow
        do i = 1, 3
            lr = log(self%inertia(i)) - log(self%mass) - 2.0_dp*log(sus%b_prime)
            if (lr < log(INERTIA_MIN) .or. lr > log(INERTIA_MAX)) then
                call bad(stat, 'body', 'inertia', rlist_short(self%inertia), TRI_NAMES(i)// &
                         '/(mass b_prime^2) = '//sci(exp(max(-700.0_dp, min(700.0_dp, lr))))// &
                         ' out of range (mass = '//rshort(self%mass)//', b_prime = '// &
                         rshort(sus%b_prime)//')', rshort(INERTIA_MIN)//' <= I/(mass b_prime^2)'// &
                         ' <= '//rshort(INERTIA_MAX)//' for each principal moment')
                return
            end if
        end do
        ! triangle inequalities, in halves so that nothing overflows
        half = 0.5_dp*self%inertia
        slack = TRIANGLE_SLACK*maxval(half)
        do i = 1, 3
            t = half
            t(i) = 0.0_dp
            if (half(i) - t(1) - t(2) - t(3) > slack) then
                j = modulo(i, 3) + 1
                call bad(stat, 'body', 'inertia', rlist_short(self%inertia), TRI_NAMES(i)// &
                         ' > '//TRI_NAMES(j)//' + '//TRI_NAMES(modulo(j, 3) + 1)// &
                         ' violates the triangle inequality', &
                         'each principal moment <= the sum of the other two')
                return
            end if
        end do
        ! the mass centre as measured: its depth below CD and offset along it
        if ((self%gave('cg_depth') .or. self%gave('cg_offset')) .and. &
            (self%gave('r') .or. self%gave('lambda'))) then
            call bad(stat, 'body', trim(merge('cg_depth ', 'cg_offset', self%gave(&
                     'cg_depth'))), rshort(merge(self%cg_depth, self%cg_offset, self%gave(&
                     'cg_depth'))), 'given with '//trim(merge('r     ', 'lambda', self%gave(&
                     'r'))), 'the mass centre either as cg_depth, cg_offset (as measured) or '// &
                     'as r, lambda (the paper''s), not both')
            return
        end if
        if (sus%cables > 2 .and. (self%gave('r') .or. self%gave('lambda'))) then
            call bad(stat, 'body', trim(merge('r     ', 'lambda', self%gave('r'))), &
                     rshort(merge(self%r, self%lambda, self%gave('r'))), 'the paper''s '// &
                     'place of the mass centre on a platform of '//itoa(sus%cables)//' cables', &
                     'the mass centre of a platform as cg_offset = x, y (in the body''s '// &
                     'frame) and cg_depth (below the plane of the attachments)')
            return
        end if
        if (sus%cables <= 2 .and. self%gave('cg_offset_y')) then
            call bad(stat, 'body', 'cg_offset', rshort(self%cg_offset)//', '// &
                     rshort(self%cg_offset_y), 'two values on a bifilar', 'one value on a '// &
                     'bifilar (the offset along CD from its midpoint), two (x, y in the '// &
                     'body''s frame) on a platform of cables >= 3')
            return
        end if
        if (self%centre_measured(sus)) then
            call finite(stat, 'body', 'cg_depth', self%cg_depth)
            call finite(stat, 'body', 'cg_offset', self%cg_offset)
            if (stat%code /= STATUS_OK) return
            if (self%cg_depth /= 0.0_dp) call over_b_prime(stat, 'body', 'cg_depth', &
                                                           self%cg_depth, sus%b_prime, 0.0_dp)
            if (self%cg_offset /= 0.0_dp) call over_b_prime(stat, 'body', 'cg_offset', &
                                                          self%cg_offset, sus%b_prime, 0.0_dp)
            call finite(stat, 'body', 'cg_offset(2)', self%cg_offset_y)
            if (self%cg_offset_y /= 0.0_dp) call over_b_prime(stat, 'body', 'cg_offset(2)', &
                                                            self%cg_offset_y, sus%b_prime, 0.0_dp)
            if (stat%code /= STATUS_OK) return
        end if
        ! r and lambda as the run takes them (from cg_depth and cg_offset: normalise)
        r = self%r
        lambda = self%lambda
        if (self%centre_measured(sus)) call self%centre(sus%b_prime, r, lambda)
        call finite(stat, 'body', 'r', r)
        call finite(stat, 'body', 'lambda', lambda)
        if (stat%code /= STATUS_OK) return
        if (r < 0.0_dp) then
            call bad(stat, 'body', 'r', rshort(r), 'negative distance', 'r >= 0')
            return
        end if
        if (r > 0.0_dp) call over_b_prime(stat, 'body', 'r', r, sus%b_prime, 0.0_dp)
        call angle(stat, 'body', 'lambda', lambda)
        if (stat%code /= STATUS_OK) return
        do i = 1, 3
            do j = 1, 3
                call finite(stat, 'body', 'btilde('//achar(iachar('0') + i)//','// &
                            achar(iachar('0') + j)//')', self%btilde(i, j))
            end do
        end do
        if (stat%code /= STATUS_OK) return
        if (any(abs(self%btilde) > 1.0_dp + ORTHO_TOL)) then
            call bad(stat, 'body', 'btilde', btilde_short(self%btilde), 'an element ' // &
                     'exceeds 1 in magnitude, rows are not orthonormal', ortho_allowed())
            return
        end if
        mmt = matmul(self%btilde, transpose(self%btilde))
        err = -1.0_dp
        iw = 0
        jw = 0
        do j = 1, 3
            do i = 1, j
                if (i == j) then
                    if (abs(mmt(i, j) - 1.0_dp) > err) then
                        err = abs(mmt(i, j) - 1.0_dp)
                        iw = i
                        jw = j
                    end if
                else if (abs(mmt(i, j)) > err) then
                    err = abs(mmt(i, j))
                    iw = i
                    jw = j
                end if
            end do
        end do
        if (err > ORTHO_TOL) then
            if (iw == jw) then
                call bad(stat, 'body', 'btilde', btilde_short(self%btilde), 'row '// &
                         achar(iachar('0') + iw)//' is not a unit vector (length^2 = '// &
                         rshort(mmt(iw, iw))//')', ortho_allowed())
            else
                call bad(stat, 'body', 'btilde', btilde_short(self%btilde), 'rows '// &
                         achar(iachar('0') + iw)//' and '//achar(iachar('0') + jw)// &
                         ' are not orthogonal (dot product = '//rshort(mmt(iw, jw))//')', &
                         ortho_allowed())
            end if
            return
        end if
        associate (bt => self%btilde)
            det = bt(1, 1)*(bt(2, 2)*bt(3, 3) - bt(2, 3)*bt(3, 2)) &
                - bt(1, 2)*(bt(2, 1)*bt(3, 3) - bt(2, 3)*bt(3, 1)) &
                + bt(1, 3)*(bt(2, 1)*bt(3, 2) - bt(2, 2)*bt(3, 1))
        end associate
        if (det < 0.0_dp) then
            call bad(stat, 'body', 'btilde', btilde_short(self%btilde), 'left-handed ' // &
                     '(determinant = '//rshort(det)//')', 'a right-handed orthonormal ' // &
                     'matrix, determinant +1; change the sign of one row')
            return
        end if
        call finite(stat, 'body', 'sway_depth', self%sway_depth)
        if (stat%code /= STATUS_OK) return
        if (self%sway_depth /= 0.0_dp) call over_b_prime(stat, 'body', 'sway_depth', &
                                                       self%sway_depth, sus%b_prime, 0.0_dp)
    end procedure check_body

    !> &start: finite values; for mode 'raised' 0 < amplitude < 180 degrees; |angles| at most
    !! ANGLE_MAX (they are reduced modulo 2 pi by normalise), |rates| at most RATE_MAX.
    module procedure check_start
        integer :: i
        character(len=len(self%mode)) :: mode
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'start', 'mode', self%mode, 'raised angles')
        if (stat%code /= STATUS_OK) return
        mode = lower(adjustl(self%mode))
        call finite(stat, 'start', 'amplitude', self%amplitude)
        call finite(stat, 'start', 'tilt', self%tilt)
        call finite(stat, 'start', 'sway', self%sway)
        if (stat%code == STATUS_OK .and. abs(self%sway) > 0.5_dp) call bad(stat, 'start', &
            'sway', rshort(self%sway), 'out of range', '|sway| <= 0.5 rad (the cables'' '// &
            'swing out of their plane at the release: a small angle)')
        do i = 1, 4
            call finite(stat, 'start', 'theta', self%theta(i))
            call finite(stat, 'start', 'theta_dot', self%theta_dot(i))
        end do
        if (stat%code /= STATUS_OK) return
        call angle(stat, 'start', 'tilt', self%tilt)
        do i = 1, 4
            call angle(stat, 'start', 'theta', self%theta(i))
        end do
        do i = 1, 4
            if (abs(self%theta_dot(i)) > RATE_MAX) call bad(stat, 'start', 'theta_dot', &
                rlist_short(self%theta_dot), 'a rate beyond '//rshort(RATE_MAX)// &
                ' rad per unit tau', '|theta_dot| <= '//rshort(RATE_MAX)// &
                ' (rad per unit tau; the natural frequencies are of order 1)')
        end do
        if (stat%code /= STATUS_OK) return
        if (trim(mode) == 'raised') then
            if (self%amplitude <= 0.0_dp .or. self%amplitude >= 180.0_dp) then
                call bad(stat, 'start', 'amplitude', rshort(self%amplitude), &
                         'out of range for mode ''raised''', '0 < amplitude < 180 (degrees)')
            end if
        end if
    end procedure check_start

    !> &integration: 0 < dtau_out <= tau_end, at most MAX_ROWS rows, tolerances in range.
    module procedure check_integration
        character(len=len(self%sensitivities)) :: sens
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'integration', 'method', self%method, METHODS_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'integration', 'sensitivities', self%sensitivities, &
                        SENSITIVITIES_ALLOWED)
        if (stat%code /= STATUS_OK) return
        sens = lower(adjustl(self%sensitivities))
        if (self%sensitivity_error_control .and. trim(sens) /= 'forward') then
            call set_error(stat, ERR_DECK, '&integration sensitivity_error_control = '// &
                           '.true.: there are no forward sensitivities to control with '// &
                           'sensitivities = '''//trim(sens)//'''; allowed: '// &
                           '.false., or .true. with sensitivities = ''forward''')
            return
        end if
        call positive(stat, 'integration', 'tau_end', self%tau_end, 'tau_end > 0')
        call positive(stat, 'integration', 'dtau_out', self%dtau_out, '0 < dtau_out <= tau_end')
        call finite(stat, 'integration', 'rtol', self%rtol)
        call finite(stat, 'integration', 'atol', self%atol)
        if (stat%code /= STATUS_OK) return
        if (self%tau_end > TAU_END_MAX) then
            call bad(stat, 'integration', 'tau_end', rshort(self%tau_end), 'too long a run', &
                     '0 < tau_end <= '//rshort(TAU_END_MAX)//' (units of tau)')
            return
        end if
        if (self%dtau_out > self%tau_end) then
            call bad(stat, 'integration', 'dtau_out', rshort(self%dtau_out), &
                     'larger than tau_end = '//rshort(self%tau_end), '0 < dtau_out <= tau_end')
            return
        end if
        if (self%tau_end/MAX_ROWS > self%dtau_out) then
            call bad(stat, 'integration', 'dtau_out', rshort(self%dtau_out), 'too many ' // &
                     'output rows (tau_end/dtau_out > '//rshort(MAX_ROWS)//', tau_end = '// &
                     rshort(self%tau_end)//')', 'tau_end/dtau_out <= '//rshort(MAX_ROWS)// &
                     ' (the row limit, about 40 MB of .dat)')
            return
        end if
        if (self%rtol < RTOL_MIN .or. self%rtol >= 1.0_dp) then
            call bad(stat, 'integration', 'rtol', rshort(self%rtol), 'relative tolerance ' // &
                     'out of range', '1e-14 <= rtol < 1 (smallest allowed 1e-14)')
            return
        end if
        if (self%atol <= 0.0_dp) then
            call bad(stat, 'integration', 'atol', rshort(self%atol), 'absolute tolerance ' // &
                     'must be > 0', 'atol > 0')
            return
        end if
        ! below ATOL_MIN the integrator's error weights overflow on a state component at 0
        if (self%atol < ATOL_MIN .or. self%atol > ATOL_MAX) then
            call bad(stat, 'integration', 'atol', rshort(self%atol), 'absolute tolerance ' // &
                     'out of range', '1e-30 <= atol <= 1 (radians and rad per unit tau)')
        end if
    end procedure check_integration

    !> &cables (read and checked whatever the model, used by model = 'elastic').
    module procedure check_cables
        if (stat%code /= STATUS_OK) return
        call finite(stat, 'cables', 'stiffness', self%stiffness)
        call finite(stat, 'cables', 'damping', self%damping)
        if (stat%code /= STATUS_OK) return
        if (self%stiffness < STIFFNESS_MIN .or. self%stiffness > STIFFNESS_MAX) then
            call bad(stat, 'cables', 'stiffness', rshort(self%stiffness), &
                     'axial stiffness EA/(m g) out of range', '1 <= stiffness <= 1e12')
            return
        end if
        if (self%damping < 0.0_dp .or. self%damping > DAMPING_MAX) then
            call bad(stat, 'cables', 'damping', rshort(self%damping), &
                     'damping ratio out of range', '0 <= damping <= 10 (fraction of critical)')
        end if
    end procedure check_cables

    !> &damping: c_v, c_q finite and >= 0, each at most DAMPING_SCALED_MAX in the model's
    !! scaled units (c_v / (m b' sqrt(g b')), c_q / (m b'^2)).
    module procedure check_damping
        if (stat%code /= STATUS_OK) return
        call one('c_v', self%c_v, log(bod%mass) + 1.5_dp*log(sus%b_prime) + 0.5_dp*log(sus%g), &
                 'c_v/(mass b_prime sqrt(g b_prime))')
        call one('c_q', self%c_q, log(bod%mass) + 2.0_dp*log(sus%b_prime), 'c_q/(mass b_prime^2)')
    contains
        subroutine one(var, x, lscale, scaled)
            character(len=*), intent(in) :: var, scaled
            real(dp), intent(in) :: x               !! the coefficient (deck units)
            real(dp), intent(in) :: lscale          !! log of its scale
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'damping', var, x)
            if (stat%code /= STATUS_OK) return
            if (x < 0.0_dp) then
                call bad(stat, 'damping', var, rshort(x), 'negative damping feeds energy '// &
                         'into the swing', var//' >= 0 (deck units: torque per rate'// &
                         trim(merge(' squared', '        ', var == 'c_q'))//')')
            else if (x > 0.0_dp) then
                if (log(x) - lscale > log(DAMPING_SCALED_MAX)) call bad(stat, 'damping', var, &
                    rshort(x), scaled//' = '//sci(exp(min(700.0_dp, log(x) - lscale)))// &
                    ' out of range', scaled//' <= '//rshort(DAMPING_SCALED_MAX)// &
                    ' (critical damping of torsion is of order 1 in these units)')
            end if
        end subroutine one
    end procedure check_damping

    pure function ortho_allowed() result(s)
        character(len=:), allocatable :: s
        s = 'orthonormal rows within 1e-9 (btilde btilde^T = I) and determinant +1'
    end function ortho_allowed

    function btilde_short(bt) result(s)
        real(dp), intent(in) :: bt(3,3)             !! btilde
        character(len=:), allocatable :: s
        s = '['//rlist_short(bt(1, :))//'; '//rlist_short(bt(2, :))//'; '// &
            rlist_short(bt(3, :))//']'
    end function btilde_short

end submodule rig_checks
