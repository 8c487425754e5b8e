!> The checks of the deck's values, one check_<group> per namelist group (submodule of
!! deck): each value finite and in its range, words known, the first problem an ERR_DECK
!! status naming the group, the variable, its value, what is wrong and what is allowed.
!! The checks run in the order of the groups; each returns at once when an earlier one
!! failed.
submodule (deck) deck_checks
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use text, only: sci, count_words
    implicit none

contains

    !> &scene: model a known word, analyses known words (at least one); both normalised to
    !! lower case, tabs in analyses taken as blanks.
    module procedure check_scene
        integer :: k
        if (stat%code /= STATUS_OK) return
        do k = 1, len(d%analyses)
            if (d%analyses(k:k) == achar(9)) d%analyses(k:k) = ' '
        end do
        d%analyses = adjustl(d%analyses)
        call check_word(stat, 'scene', 'model', d%model, MODELS_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_analyses(stat, d%analyses)
        if (stat%code /= STATUS_OK) return
        d%analyses = lower(adjustl(d%analyses))
        d%model = lower(adjustl(d%model))
    end procedure check_scene

    !> &output: the columns, blank-separated names of OUTPUT_COLUMNS (check_columns), put in
    !! OUTPUT_COLUMNS' order.
    module procedure check_output
        character(len=len(d%columns)) :: asked
        if (stat%code /= STATUS_OK) return
        asked = d%columns
        call check_columns(stat, asked, d%columns)
    end procedure check_output

    !> &suspension: all lengths and g finite, > 0 and within DIM_MIN .. DIM_MAX; b, l, l'
    !! over b' within RATIO_MIN .. RATIO_MAX.
    module procedure check_suspension
        if (stat%code /= STATUS_OK) return
        if (d%cables < 2 .or. d%cables > MAX_CABLES) then
            call bad(stat, 'suspension', 'cables', itoa(d%cables), 'number of cables out of '// &
                     'range', '2 (a bifilar) .. '//itoa(MAX_CABLES)//' (a platform on that many '// &
                     'cables at radius and radius_prime)')
            return
        end if
        if (d%cables == 2) then
            if (deck_gave(d, 'radius') .or. deck_gave(d, 'radius_prime')) then
                call bad(stat, 'suspension', trim(merge('radius      ', 'radius_prime', &
                         deck_gave(d, 'radius'))), rshort(merge(d%radius, d%radius_prime, &
                         deck_gave(d, 'radius'))), 'a platform''s radius with cables = 2', &
                         'b and b_prime (the full distances between the two cables) for a '// &
                         'bifilar; radius and radius_prime with cables >= 3')
                return
            end if
        else
            ! a platform: its cables at one radius; the equivalent pair b = 2 R, b' = 2 R'
            if (deck_gave(d, 'b') .or. deck_gave(d, 'b_prime')) then
                call bad(stat, 'suspension', trim(merge('b      ', 'b_prime', deck_gave(d, &
                         'b'))), rshort(merge(d%b, d%b_prime, deck_gave(d, 'b'))), &
                         'a bifilar''s spacing with cables = '//itoa(d%cables), 'radius and '// &
                         'radius_prime (the radii of the attachment circles on the support and '// &
                         'the body) with cables >= 3')
                return
            end if
            call positive(stat, 'suspension', 'radius', d%radius, 'radius > 0 with cables >= 3')
            call positive(stat, 'suspension', 'radius_prime', d%radius_prime, &
                          'radius_prime > 0 with cables >= 3')
            if (stat%code /= STATUS_OK) return
            if (deck_gave(d, 'l_prime') .and. d%l_prime /= d%l) then
                call bad(stat, 'suspension', 'l_prime', rshort(d%l_prime), 'differs from l = '// &
                         rshort(d%l)//' on a platform of '//itoa(d%cables)//' cables', &
                         'every cable of length l (leave l_prime out) with cables >= 3')
                return
            end if
            d%b = 2.0_dp*d%radius
            d%b_prime = 2.0_dp*d%radius_prime
            d%l_prime = d%l
        end if
        call positive(stat, 'suspension', 'b', d%b, 'lengths > 0')
        call positive(stat, 'suspension', 'b_prime', d%b_prime, 'lengths > 0')
        call positive(stat, 'suspension', 'l', d%l, 'lengths > 0')
        call positive(stat, 'suspension', 'l_prime', d%l_prime, 'lengths > 0')
        call positive(stat, 'suspension', 'g', d%g, 'g > 0')
        call dimensional(stat, 'suspension', 'b_prime', d%b_prime)
        call dimensional(stat, 'suspension', 'b', d%b)
        call dimensional(stat, 'suspension', 'l', d%l)
        call dimensional(stat, 'suspension', 'l_prime', d%l_prime)
        call dimensional(stat, 'suspension', 'g', d%g)
        call over_b_prime(stat, 'suspension', 'b', d%b, d%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'suspension', 'l', d%l, d%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'suspension', 'l_prime', d%l_prime, d%b_prime, RATIO_MIN)
    end procedure check_suspension

    !> &body: mass > 0; principal moments > 0 obeying the triangle inequalities; r >= 0;
    !! btilde a right-handed orthonormal matrix; everything finite.
    module procedure check_body
        real(dp) :: t(3), half(3), slack, mmt(3,3), det, err, lr
        integer :: i, j, iw, jw
        character(len=*), parameter :: TRI_NAMES(3) = ['I1', 'I2', 'I3']
        if (stat%code /= STATUS_OK) return
        call positive(stat, 'body', 'mass', d%mass, 'mass > 0')
        do i = 1, 3
            call finite(stat, 'body', 'inertia', d%inertia(i))
        end do
        if (stat%code /= STATUS_OK) return
        if (any(d%inertia <= 0.0_dp)) then
            call bad(stat, 'body', 'inertia', rlist_short(d%inertia), &
                     'a principal moment of inertia is <= 0', 'all three > 0')
            return
        end if
        call dimensional(stat, 'body', 'mass', d%mass)
        do i = 1, 3
            call dimensional(stat, 'body', 'inertia', d%inertia(i))
        end do
        if (stat%code /= STATUS_OK) return
        ! I/(m b'^2) in logarithms: the quotient itself may overflow
        do i = 1, 3
            lr = log(d%inertia(i)) - log(d%mass) - 2.0_dp*log(d%b_prime)
            if (lr < log(INERTIA_MIN) .or. lr > log(INERTIA_MAX)) then
                call bad(stat, 'body', 'inertia', rlist_short(d%inertia), TRI_NAMES(i)// &
                         '/(mass b_prime^2) = '//sci(exp(max(-700.0_dp, min(700.0_dp, lr))))// &
                         ' out of range (mass = '//rshort(d%mass)//', b_prime = '// &
                         rshort(d%b_prime)//')', rshort(INERTIA_MIN)//' <= I/(mass b_prime^2)'// &
                         ' <= '//rshort(INERTIA_MAX)//' for each principal moment')
                return
            end if
        end do
        ! triangle inequalities, in halves so that nothing overflows
        half = 0.5_dp*d%inertia
        slack = TRIANGLE_SLACK*maxval(half)
        do i = 1, 3
            t = half
            t(i) = 0.0_dp
            if (half(i) - t(1) - t(2) - t(3) > slack) then
                j = modulo(i, 3) + 1
                call bad(stat, 'body', 'inertia', rlist_short(d%inertia), TRI_NAMES(i)// &
                         ' > '//TRI_NAMES(j)//' + '//TRI_NAMES(modulo(j, 3) + 1)// &
                         ' violates the triangle inequality', &
                         'each principal moment <= the sum of the other two')
                return
            end if
        end do
        ! the mass centre as measured: its depth below CD and offset along it
        if ((deck_gave(d, 'cg_depth') .or. deck_gave(d, 'cg_offset')) .and. &
            (deck_gave(d, 'r') .or. deck_gave(d, 'lambda'))) then
            call bad(stat, 'body', trim(merge('cg_depth ', 'cg_offset', deck_gave(d, &
                     'cg_depth'))), rshort(merge(d%cg_depth, d%cg_offset, deck_gave(d, &
                     'cg_depth'))), 'given with '//trim(merge('r     ', 'lambda', deck_gave(d, &
                     'r'))), 'the mass centre either as cg_depth, cg_offset (as measured) or '// &
                     'as r, lambda (the paper''s), not both')
            return
        end if
        if (d%cables > 2 .and. (deck_gave(d, 'r') .or. deck_gave(d, 'lambda') .or. &
                                d%cg_offset /= 0.0_dp)) then
            call bad(stat, 'body', trim(merge('cg_offset', 'r        ', d%cg_offset /= 0.0_dp)), &
                     rshort(merge(d%cg_offset, d%r, d%cg_offset /= 0.0_dp)), 'a mass centre '// &
                     'off the axis of a platform of '//itoa(d%cables)//' cables', &
                     'the mass centre on the platform''s axis: cg_depth (any), cg_offset = 0')
            return
        end if
        if (deck_gave(d, 'cg_depth') .or. deck_gave(d, 'cg_offset') .or. d%cables > 2) then
            call finite(stat, 'body', 'cg_depth', d%cg_depth)
            call finite(stat, 'body', 'cg_offset', d%cg_offset)
            if (stat%code /= STATUS_OK) return
            if (d%cg_depth /= 0.0_dp) call over_b_prime(stat, 'body', 'cg_depth', d%cg_depth, &
                                                         d%b_prime, 0.0_dp)
            if (d%cg_offset /= 0.0_dp) call over_b_prime(stat, 'body', 'cg_offset', &
                                                          d%cg_offset, d%b_prime, 0.0_dp)
            if (stat%code /= STATUS_OK) return
            d%r = sqrt((0.5_dp*d%b_prime + d%cg_offset)**2 + d%cg_depth**2)
            d%lambda = atan2(d%cg_depth, 0.5_dp*d%b_prime + d%cg_offset)
        end if
        call finite(stat, 'body', 'r', d%r)
        call finite(stat, 'body', 'lambda', d%lambda)
        if (stat%code /= STATUS_OK) return
        if (d%r < 0.0_dp) then
            call bad(stat, 'body', 'r', rshort(d%r), 'negative distance', 'r >= 0')
            return
        end if
        if (d%r > 0.0_dp) call over_b_prime(stat, 'body', 'r', d%r, d%b_prime, 0.0_dp)
        call angle(stat, 'body', 'lambda', d%lambda)
        if (stat%code /= STATUS_OK) return
        do i = 1, 3
            do j = 1, 3
                call finite(stat, 'body', 'btilde('//achar(iachar('0') + i)//','// &
                            achar(iachar('0') + j)//')', d%btilde(i, j))
            end do
        end do
        if (stat%code /= STATUS_OK) return
        if (any(abs(d%btilde) > 1.0_dp + ORTHO_TOL)) then
            call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'an element ' // &
                     'exceeds 1 in magnitude, rows are not orthonormal', ortho_allowed())
            return
        end if
        mmt = matmul(d%btilde, transpose(d%btilde))
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
                call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'row '// &
                         achar(iachar('0') + iw)//' is not a unit vector (length^2 = '// &
                         rshort(mmt(iw, iw))//')', ortho_allowed())
            else
                call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'rows '// &
                         achar(iachar('0') + iw)//' and '//achar(iachar('0') + jw)// &
                         ' are not orthogonal (dot product = '//rshort(mmt(iw, jw))//')', &
                         ortho_allowed())
            end if
            return
        end if
        det = d%btilde(1, 1)*(d%btilde(2, 2)*d%btilde(3, 3) - d%btilde(2, 3)*d%btilde(3, 2)) &
            - d%btilde(1, 2)*(d%btilde(2, 1)*d%btilde(3, 3) - d%btilde(2, 3)*d%btilde(3, 1)) &
            + d%btilde(1, 3)*(d%btilde(2, 1)*d%btilde(3, 2) - d%btilde(2, 2)*d%btilde(3, 1))
        if (det < 0.0_dp) then
            call bad(stat, 'body', 'btilde', btilde_short(d%btilde), 'left-handed ' // &
                     '(determinant = '//rshort(det)//')', 'a right-handed orthonormal ' // &
                     'matrix, determinant +1; change the sign of one row')
            return
        end if
        call finite(stat, 'body', 'sway_depth', d%sway_depth)
        if (stat%code /= STATUS_OK) return
        if (d%sway_depth /= 0.0_dp) call over_b_prime(stat, 'body', 'sway_depth', &
                                                       d%sway_depth, d%b_prime, 0.0_dp)
    end procedure check_body

    !> &start: finite values; for mode 'raised' 0 < amplitude < 180 degrees; |angles| at most
    !! ANGLE_MAX (they are reduced modulo 2 pi by reduce_angles), |rates| at most RATE_MAX.
    module procedure check_start
        integer :: i
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'start', 'mode', d%mode, 'raised angles')
        if (stat%code /= STATUS_OK) return
        d%mode = lower(adjustl(d%mode))
        call finite(stat, 'start', 'amplitude', d%amplitude)
        call finite(stat, 'start', 'tilt', d%tilt)
        do i = 1, 4
            call finite(stat, 'start', 'theta', d%theta(i))
            call finite(stat, 'start', 'theta_dot', d%theta_dot(i))
        end do
        if (stat%code /= STATUS_OK) return
        call angle(stat, 'start', 'tilt', d%tilt)
        do i = 1, 4
            call angle(stat, 'start', 'theta', d%theta(i))
        end do
        do i = 1, 4
            if (abs(d%theta_dot(i)) > RATE_MAX) call bad(stat, 'start', 'theta_dot', &
                rlist_short(d%theta_dot), 'a rate beyond '//rshort(RATE_MAX)// &
                ' rad per unit tau', '|theta_dot| <= '//rshort(RATE_MAX)// &
                ' (rad per unit tau; the natural frequencies are of order 1)')
        end do
        if (stat%code /= STATUS_OK) return
        if (trim(d%mode) == 'raised') then
            if (d%amplitude <= 0.0_dp .or. d%amplitude >= 180.0_dp) then
                call bad(stat, 'start', 'amplitude', rshort(d%amplitude), &
                         'out of range for mode ''raised''', '0 < amplitude < 180 (degrees)')
            end if
        end if
    end procedure check_start

    !> &integration: 0 < dtau_out <= tau_end, at most MAX_ROWS rows, tolerances in range.
    module procedure check_integration
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'integration', 'method', d%method, METHODS_ALLOWED)
        if (stat%code /= STATUS_OK) return
        d%method = lower(adjustl(d%method))
        call check_word(stat, 'integration', 'sensitivities', d%sensitivities, &
                        SENSITIVITIES_ALLOWED)
        if (stat%code /= STATUS_OK) return
        d%sensitivities = lower(adjustl(d%sensitivities))
        if (d%sensitivity_error_control .and. trim(d%sensitivities) /= 'forward') then
            call set_error(stat, ERR_DECK, '&integration sensitivity_error_control = '// &
                           '.true.: there are no forward sensitivities to control with '// &
                           'sensitivities = '''//trim(d%sensitivities)//'''; allowed: '// &
                           '.false., or .true. with sensitivities = ''forward''')
            return
        end if
        call positive(stat, 'integration', 'tau_end', d%tau_end, 'tau_end > 0')
        call positive(stat, 'integration', 'dtau_out', d%dtau_out, '0 < dtau_out <= tau_end')
        call finite(stat, 'integration', 'rtol', d%rtol)
        call finite(stat, 'integration', 'atol', d%atol)
        if (stat%code /= STATUS_OK) return
        if (d%tau_end > TAU_END_MAX) then
            call bad(stat, 'integration', 'tau_end', rshort(d%tau_end), 'too long a run', &
                     '0 < tau_end <= '//rshort(TAU_END_MAX)//' (units of tau)')
            return
        end if
        if (d%dtau_out > d%tau_end) then
            call bad(stat, 'integration', 'dtau_out', rshort(d%dtau_out), &
                     'larger than tau_end = '//rshort(d%tau_end), '0 < dtau_out <= tau_end')
            return
        end if
        if (d%tau_end/MAX_ROWS > d%dtau_out) then
            call bad(stat, 'integration', 'dtau_out', rshort(d%dtau_out), 'too many ' // &
                     'output rows (tau_end/dtau_out > '//rshort(MAX_ROWS)//', tau_end = '// &
                     rshort(d%tau_end)//')', 'tau_end/dtau_out <= '//rshort(MAX_ROWS)// &
                     ' (the row limit, about 40 MB of .dat)')
            return
        end if
        if (d%rtol < RTOL_MIN .or. d%rtol >= 1.0_dp) then
            call bad(stat, 'integration', 'rtol', rshort(d%rtol), 'relative tolerance ' // &
                     'out of range', '1e-14 <= rtol < 1 (smallest allowed 1e-14)')
            return
        end if
        if (d%atol <= 0.0_dp) then
            call bad(stat, 'integration', 'atol', rshort(d%atol), 'absolute tolerance ' // &
                     'must be > 0', 'atol > 0')
            return
        end if
        ! below ATOL_MIN the integrator's error weights overflow on a state component at 0
        if (d%atol < ATOL_MIN .or. d%atol > ATOL_MAX) then
            call bad(stat, 'integration', 'atol', rshort(d%atol), 'absolute tolerance ' // &
                     'out of range', '1e-30 <= atol <= 1 (radians and rad per unit tau)')
        end if
    end procedure check_integration

    !> &cables (read and checked whatever the model, used by model = 'elastic').
    module procedure check_cables
        if (stat%code /= STATUS_OK) return
        call finite(stat, 'cables', 'stiffness', d%cable_stiffness)
        call finite(stat, 'cables', 'damping', d%cable_damping)
        if (stat%code /= STATUS_OK) return
        if (d%cable_stiffness < STIFFNESS_MIN .or. d%cable_stiffness > STIFFNESS_MAX) then
            call bad(stat, 'cables', 'stiffness', rshort(d%cable_stiffness), &
                     'axial stiffness EA/(m g) out of range', '1 <= stiffness <= 1e12')
            return
        end if
        if (d%cable_damping < 0.0_dp .or. d%cable_damping > DAMPING_MAX) then
            call bad(stat, 'cables', 'damping', rshort(d%cable_damping), &
                     'damping ratio out of range', '0 <= damping <= 10 (fraction of critical)')
        end if
    end procedure check_cables

    !> &damping: c_v, c_q finite and >= 0, each at most DAMPING_SCALED_MAX in the model's
    !! scaled units (c_v / (m b' sqrt(g b')), c_q / (m b'^2)).
    module procedure check_damping
        if (stat%code /= STATUS_OK) return
        call one('c_v', d%c_v, log(d%mass) + 1.5_dp*log(d%b_prime) + 0.5_dp*log(d%g), &
                 'c_v/(mass b_prime sqrt(g b_prime))')
        call one('c_q', d%c_q, log(d%mass) + 2.0_dp*log(d%b_prime), 'c_q/(mass b_prime^2)')
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

    !> &measurement: periods given without gaps, each finite, > 0 and at most DIM_MAX, one
    !! amplitude (0 < a < 180 degrees) per period and no more; uncertainties finite, >= 0
    !! and at most DIM_MAX; 0 or 2 .. MAX_MONTE_CARLO Monte Carlo samples.  (quantity and
    !! estimate are checked by read_deck; what identify needs of them, by identify_ready.)
    module procedure check_measurement
        integer :: i, na, nc
        character(len=16) :: nm
        logical :: unit_rate
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'measurement', 'quantity', d%quantity, QUANTITIES_ALLOWED)
        if (stat%code /= STATUS_OK) return
        call check_estimate(stat, d%estimate)
        if (stat%code /= STATUS_OK) return
        d%quantity = lower(adjustl(d%quantity))
        do i = d%n_periods + 1, MAX_PERIODS
            if (d%periods(i) /= PERIOD_UNSET) then
                call bad(stat, 'measurement', 'periods('//itoa(i)//')', rshort(d%periods(i)), &
                         'given after a period left out (periods('//itoa(d%n_periods + 1)// &
                         '))', 'periods(1), periods(2), ... without gaps, at most '// &
                         itoa(MAX_PERIODS))
                return
            end if
        end do
        na = 0
        do while (na < MAX_PERIODS)
            if (d%amplitudes(na + 1) == PERIOD_UNSET) exit
            na = na + 1
        end do
        do i = na + 1, MAX_PERIODS
            if (d%amplitudes(i) /= PERIOD_UNSET) then
                call bad(stat, 'measurement', 'amplitudes('//itoa(i)//')', &
                         rshort(d%amplitudes(i)), 'given after an amplitude left out '// &
                         '(amplitudes('//itoa(na + 1)//'))', 'one amplitude per period, '// &
                         'without gaps')
                return
            end if
        end do
        if (na /= d%n_periods) then
            call bad(stat, 'measurement', 'amplitudes', itoa(na)//' values', 'there are '// &
                     itoa(d%n_periods)//' periods', 'one amplitude (degrees of theta4 at the '// &
                     'peak) per period')
            return
        end if
        do i = 1, d%n_periods
            nm = 'periods('//itoa(i)//')'
            call positive(stat, 'measurement', trim(nm), d%periods(i), 'periods > 0 (s)')
            call dimensional(stat, 'measurement', trim(nm), d%periods(i))
            nm = 'amplitudes('//itoa(i)//')'
            call finite(stat, 'measurement', trim(nm), d%amplitudes(i))
            if (stat%code /= STATUS_OK) return
            if (d%amplitudes(i) <= 0.0_dp .or. d%amplitudes(i) >= 180.0_dp) then
                call bad(stat, 'measurement', trim(nm), rshort(d%amplitudes(i)), &
                         'out of range', '0 < amplitude < 180 (degrees of theta4 at the peak)')
                return
            end if
        end do
        call uncertainty('u_mass', d%u_mass)
        call uncertainty('u_l', d%u_l)
        call uncertainty('u_l_prime', d%u_l_prime)
        call uncertainty('u_b', d%u_b)
        call uncertainty('u_b_prime', d%u_b_prime)
        call uncertainty('u_g', d%u_g)
        call uncertainty('u_period', d%u_period)
        call uncertainty('u_amplitude', d%u_amplitude)
        if (stat%code /= STATUS_OK) return
        ! cycles: none (1 each), one value for every period, or one per period
        nc = count(d%cycles /= PERIOD_UNSET)
        if (nc > 0) then
            if (any(d%cycles(nc + 1:) /= PERIOD_UNSET)) then
                call bad(stat, 'measurement', 'cycles', 'with a gap', 'a value given after '// &
                         'one left out', 'cycles = N (every period the time of N cycles) or '// &
                         'one value per period, without gaps')
                return
            end if
            if (nc /= 1 .and. nc /= d%n_periods) then
                call bad(stat, 'measurement', 'cycles', itoa(nc)//' values', 'there are '// &
                         itoa(d%n_periods)//' periods', 'cycles = N (every period the time of '// &
                         'N cycles) or one value per period')
                return
            end if
            do i = 1, nc
                call finite(stat, 'measurement', 'cycles('//itoa(i)//')', d%cycles(i))
                if (stat%code /= STATUS_OK) return
                if (d%cycles(i) < 0.5_dp .or. d%cycles(i) > 1.0e6_dp) then
                    call bad(stat, 'measurement', 'cycles('//itoa(i)//')', rshort(d%cycles(i)), &
                             'out of range', '0.5 <= cycles <= 1e6 (the number of cycles the '// &
                             'period''s time spans)')
                    return
                end if
            end do
            if (nc == 1) d%cycles(2:max(1, d%n_periods)) = d%cycles(1)
        end if
        where (d%cycles == PERIOD_UNSET) d%cycles = 1.0_dp
        ! the record's columns and units
        if (deck_gave(d, 'record_columns') .and. (any(d%record_columns(1:2) < 1) .or. &
            any(d%record_columns > 100) .or. d%record_columns(1) == d%record_columns(2) .or. &
            (d%record_columns(3) > 0 .and. (d%record_columns(3) == d%record_columns(1) .or. &
             d%record_columns(3) == d%record_columns(2))))) then
            call bad(stat, 'measurement', 'record_columns', itoa(d%record_columns(1))//', '// &
                     itoa(d%record_columns(2))//', '//itoa(d%record_columns(3)), 'not three '// &
                     'distinct columns', 'record_columns = T, V or T, V, U: the 1-based '// &
                     'columns of time (s), value and each sample''s standard uncertainty, '// &
                     'distinct, at most 100')
            return
        end if
        if (len_trim(d%record_units) > 0) then
            call check_word(stat, 'measurement', 'record_units', d%record_units, &
                            RECORD_UNITS_ALLOWED)
            if (stat%code /= STATUS_OK) return
            d%record_units = lower(adjustl(d%record_units))
            unit_rate = index(d%record_units, '/s') > 0
            if (deck_gave(d, 'quantity') .and. ((trim(d%quantity) == 'rate') .neqv. unit_rate)) then
                call bad(stat, 'measurement', 'record_units', quoted(d%record_units), &
                         'a '//trim(merge('rate ', 'angle', unit_rate))//' with quantity = '// &
                         quoted(d%quantity), 'rad or deg with quantity = ''angle'', rad/s or '// &
                         'deg/s with quantity = ''rate'' (or leave quantity out: the units '// &
                         'imply it)')
                return
            end if
            d%quantity = merge('rate ', 'angle', unit_rate)
        end if
        call check_word(stat, 'measurement', 'loss', d%loss, LOSSES_ALLOWED)
        if (stat%code /= STATUS_OK) return
        d%loss = lower(adjustl(d%loss))
        if (d%n_periods > 0 .and. len_trim(d%trials) > 0) then
            call bad(stat, 'measurement', 'trials', quoted(d%trials), 'given with periods', &
                     'periods (one release) or trials = ''FILE'' (a table of releases), not '// &
                     'both')
            return
        end if
        if (len_trim(d%record) > 0 .and. len_trim(d%trials) > 0) then
            call bad(stat, 'measurement', 'trials', quoted(d%trials), 'given with record', &
                     'record (one release) or trials = ''FILE'' (a table of releases, with a '// &
                     'column record), not both')
            return
        end if
        call uncertainty('u_inertia', d%u_inertia(1))
        call uncertainty('u_inertia', d%u_inertia(2))
        call uncertainty('u_cg_depth', d%u_cg_depth)
        call uncertainty('u_cg_offset', d%u_cg_offset)
        call uncertainty('u_r', d%u_r)
        call uncertainty('u_lambda', d%u_lambda)
        call uncertainty('u_tare_i1', d%u_tare_i1)
        call uncertainty('u_added_inertia', d%u_added_inertia)
        call uncertainty('tare_i1', d%tare_i1)
        call uncertainty('added_inertia', d%added_inertia)
        call uncertainty('tare_mass', d%tare_mass)
        if (stat%code /= STATUS_OK) return
        if ((d%u_cg_depth > 0.0_dp .or. d%u_cg_offset > 0.0_dp) .and. .not. &
            (deck_gave(d, 'cg_depth') .or. deck_gave(d, 'cg_offset') .or. d%cables > 2)) then
            call bad(stat, 'measurement', trim(merge('u_cg_depth ', 'u_cg_offset', &
                     d%u_cg_depth > 0.0_dp)), rshort(max(d%u_cg_depth, d%u_cg_offset)), &
                     'the mass centre is given as r, lambda', 'u_r, u_lambda with r, lambda; '// &
                     'u_cg_depth, u_cg_offset with cg_depth, cg_offset')
            return
        end if
        if ((d%u_r > 0.0_dp .or. d%u_lambda > 0.0_dp) .and. (deck_gave(d, 'cg_depth') .or. &
            deck_gave(d, 'cg_offset') .or. d%cables > 2)) then
            call bad(stat, 'measurement', trim(merge('u_r     ', 'u_lambda', d%u_r > 0.0_dp)), &
                     rshort(max(d%u_r, d%u_lambda)), 'the mass centre is given as cg_depth, '// &
                     'cg_offset', 'u_cg_depth, u_cg_offset with cg_depth, cg_offset; u_r, '// &
                     'u_lambda with r, lambda')
            return
        end if
        ! a u whose 5-sigma range leaves its input's domain: the Monte Carlo would draw
        ! values no rig has (l < 0, g < 0, an amplitude beyond 180 degrees), the budget's
        ! steps would cross the edge
        call in_domain(stat, 'measurement', 'u_mass', d%u_mass, 'mass', d%mass, 0.0_dp, &
                       0.0_dp)
        call in_domain(stat, 'measurement', 'u_l', d%u_l, 'l', d%l, 0.0_dp, 0.0_dp)
        if (d%cables == 2) call in_domain(stat, 'measurement', 'u_l_prime', d%u_l_prime, &
                                          'l_prime', d%l_prime, 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_b', d%u_b, 'b', d%b, 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_b_prime', d%u_b_prime, 'b_prime', d%b_prime, &
                       0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_g', d%u_g, 'g', d%g, 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_inertia', d%u_inertia(1), 'inertia(2)', &
                       d%inertia(2), 0.0_dp, 0.0_dp)
        call in_domain(stat, 'measurement', 'u_inertia', d%u_inertia(2), 'inertia(3)', &
                       d%inertia(3), 0.0_dp, 0.0_dp)
        if (.not. (deck_gave(d, 'cg_depth') .or. deck_gave(d, 'cg_offset') .or. d%cables > 2)) &
            call in_domain(stat, 'measurement', 'u_r', d%u_r, 'r', d%r, 0.0_dp, 0.0_dp, .true.)
        do i = 1, d%n_periods
            call in_domain(stat, 'measurement', 'u_period', d%u_period, 'periods('//itoa(i)// &
                           ')', d%periods(i), 0.0_dp, 0.0_dp)
            ! the period depends on |amplitude|: only 180 degrees bounds its draws
            call in_domain(stat, 'measurement', 'u_amplitude', d%u_amplitude, 'amplitudes('// &
                           itoa(i)//')', d%amplitudes(i), -180.0_dp, 180.0_dp)
        end do
        if (len_trim(d%record) > 0 .and. trim(d%mode) == 'raised' .and. .not. &
            estimated(d, 'amplitude')) call in_domain(stat, 'measurement', 'u_amplitude', &
            d%u_amplitude, 'the release amplitude (&start amplitude)', d%amplitude, 0.0_dp, &
            180.0_dp)
        if (stat%code /= STATUS_OK) return
        if (d%tare_mass >= d%mass) then
            call bad(stat, 'measurement', 'tare_mass', rshort(d%tare_mass), 'not below the '// &
                     'mass of the whole rig (&body mass = '//rshort(d%mass)//')', '0 <= '// &
                     'tare_mass < mass (the fixture''s mass; &body mass is the total hung)')
            return
        end if
        if (d%monte_carlo == 1 .or. d%monte_carlo < 0 .or. d%monte_carlo > MAX_MONTE_CARLO) &
            call bad(stat, 'measurement', 'monte_carlo', itoa(d%monte_carlo), &
                     'number of Monte Carlo samples out of range', '0 (first order only) '// &
                     'or 2 <= monte_carlo <= '//itoa(MAX_MONTE_CARLO))
    contains
        subroutine uncertainty(var, x)
            character(len=*), intent(in) :: var
            real(dp), intent(in) :: x
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'measurement', var, x)
            if (stat%code /= STATUS_OK) return
            if (x < 0.0_dp .or. x > DIM_MAX) call bad(stat, 'measurement', var, rshort(x), &
                'a standard uncertainty out of range', '0 <= '//var//' <= '// &
                rshort(DIM_MAX)//' (deck units; 0: not known)')
        end subroutine uncertainty
    end procedure check_measurement

    !> &measurement estimate: blank-separated words from ESTIMATES_ALLOWED (I1 in any case,
    !! the others in lower case too), at least one, none twice.
    subroutine check_estimate(stat, estimate)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: estimate    !! value read
        character(len=len(estimate)) :: list
        integer :: i1, i2, n
        character(len=:), allocatable :: head, allowed, seen
        list = lower(estimate)
        do i1 = 1, len(list)
            if (list(i1:i1) == achar(9)) list(i1:i1) = ' '
        end do
        head = '&measurement estimate = '''//clip(trim(adjustl(estimate)))//''': '
        allowed = 'allowed: blank-separated words from: '//commas(ESTIMATES_ALLOWED)
        seen = ' '
        n = 0
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            n = n + 1
            if (index(' '//lower(ESTIMATES_ALLOWED)//' ', ' '//list(i1:i2)//' ') == 0) then
                call set_error(stat, ERR_DECK, head//'unknown word '''//clip(list(i1:i2))// &
                               '''; '//allowed)
                return
            end if
            if (index(seen, ' '//list(i1:i2)//' ') > 0) then
                call set_error(stat, ERR_DECK, head//''''//list(i1:i2)//''' given twice; '// &
                               allowed)
                return
            end if
            seen = seen//list(i1:i2)//' '
        end do
        if (n == 0) call set_error(stat, ERR_DECK, head//'no parameter given; '//allowed)
    end subroutine check_estimate

    !> &floquet: 0 < amplitude < 180 degrees, 1..MAX_SEGMENTS segments, rtol in range.
    module procedure check_floquet
        if (stat%code /= STATUS_OK) return
        call finite(stat, 'floquet', 'amplitude', d%floquet_amplitude)
        call finite(stat, 'floquet', 'rtol', d%floquet_rtol)
        if (stat%code /= STATUS_OK) return
        if (d%floquet_amplitude < FLOQUET_AMPLITUDE_MIN .or. d%floquet_amplitude >= 180.0_dp) then
            call bad(stat, 'floquet', 'amplitude', rshort(d%floquet_amplitude), &
                     'out of range', rshort(FLOQUET_AMPLITUDE_MIN)//' <= amplitude < 180 '// &
                     '(degrees of theta4)')
            return
        end if
        if (d%floquet_segments < 1 .or. d%floquet_segments > MAX_SEGMENTS) then
            call bad(stat, 'floquet', 'segments', itoa(d%floquet_segments), &
                     'number of shooting segments out of range', '1 <= segments <= '// &
                     itoa(MAX_SEGMENTS))
            return
        end if
        if (d%floquet_rtol < RTOL_MIN .or. d%floquet_rtol >= FLOQUET_RTOL_MAX) then
            call bad(stat, 'floquet', 'rtol', rshort(d%floquet_rtol), &
                     'relative tolerance out of range', '1e-14 <= rtol < 1e-2')
        end if
    end procedure check_floquet

    !> &chart: two different variables (known words, checked by read_deck), each axis a
    !! finite range inside its variable's range with 2..MAX_CHART_N points, nx*ny bounded.
    module procedure check_chart
        if (stat%code /= STATUS_OK) return
        call check_word(stat, 'chart', 'x', d%chart_x, CHART_VARIABLES)
        call check_word(stat, 'chart', 'y', d%chart_y, CHART_VARIABLES)
        if (stat%code /= STATUS_OK) return
        d%chart_x = lower(adjustl(d%chart_x))
        d%chart_y = lower(adjustl(d%chart_y))
        if (trim(d%chart_x) == trim(d%chart_y)) then
            call bad(stat, 'chart', 'y', quoted(d%chart_y), 'the same variable as x', &
                     'y different from x, both from: '//commas(CHART_VARIABLES))
            return
        end if
        call chart_axis('x', d%chart_x, d%chart_x_min, d%chart_x_max, d%chart_nx)
        call chart_axis('y', d%chart_y, d%chart_y_min, d%chart_y_max, d%chart_ny)
        if (stat%code /= STATUS_OK) return
        if (d%chart_nx*d%chart_ny > MAX_CHART_POINTS) then
            call bad(stat, 'chart', 'ny', itoa(d%chart_ny), 'too many chart points ' // &
                     '(nx*ny = '//itoa(d%chart_nx*d%chart_ny)//', nx = '//itoa(d%chart_nx)// &
                     ')', 'nx*ny <= '//itoa(MAX_CHART_POINTS))
        end if

    contains

        !> One chart axis: finite min < max inside the range of its variable, 2..1000 points.
        subroutine chart_axis(ax, var, vmin, vmax, n)
            character(len=*), intent(in) :: ax      !! 'x' or 'y'
            character(len=*), intent(in) :: var     !! chart variable, lower case
            real(dp), intent(in) :: vmin, vmax      !! range
            integer, intent(in) :: n                !! number of points
            real(dp) :: lo, hi
            logical :: lo_in, hi_in
            character(len=:), allocatable :: desc, allowed
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'chart', ax//'_min', vmin)
            call finite(stat, 'chart', ax//'_max', vmax)
            if (stat%code /= STATUS_OK) return
            if (vmin >= vmax) then
                call bad(stat, 'chart', ax//'_max', rshort(vmax), 'not larger than '// &
                         ax//'_min = '//rshort(vmin), ax//'_min < '//ax//'_max')
                return
            end if
            ! allowed range lo .. hi of the variable, ends included when lo_in, hi_in
            lo = 0.0_dp
            hi = huge(1.0_dp)
            lo_in = .false.
            hi_in = .true.
            select case (trim(var))
            case ('l')
                desc = 'cable length l''/b'''
                lo = RATIO_MIN
                hi = RATIO_MAX
                lo_in = .true.
            case ('b')
                desc = 'b/b'''
                lo = RATIO_MIN
                hi = RATIO_MAX
                lo_in = .true.
            case ('amplitude')
                desc = 'degrees'
                lo = FLOQUET_AMPLITUDE_MIN
                lo_in = .true.
                hi = 180.0_dp
                hi_in = .false.
            case ('r')
                desc = 'r/b'''
                hi = RATIO_MAX
                lo_in = .true.
            case ('lambda')
                desc = 'radians, -pi/2 .. pi/2'
                lo = -PI_HALF
                hi = PI_HALF
                lo_in = .true.
            case default
                desc = 'I3/I1'
                hi = RATIO_MAX
            end select
            allowed = rshort(lo)//trim(merge(' <=', ' < ', lo_in))//' '//ax//'_min < '// &
                ax//'_max'
            if (hi < huge(1.0_dp)) allowed = allowed//trim(merge(' <=', ' < ', hi_in))//' '// &
                rshort(hi)
            allowed = allowed//' for '//trim(var)//' ('//desc//')'
            if (vmin < lo .or. (vmin == lo .and. .not. lo_in)) then
                call bad(stat, 'chart', ax//'_min', rshort(vmin), 'outside the ' // &
                         'range of '//trim(var), allowed)
                return
            end if
            if (vmax > hi .or. (vmax == hi .and. .not. hi_in)) then
                call bad(stat, 'chart', ax//'_max', rshort(vmax), 'outside the ' // &
                         'range of '//trim(var), allowed)
                return
            end if
            if (n < 2 .or. n > MAX_CHART_N) then
                call bad(stat, 'chart', 'n'//ax, itoa(n), 'number of chart points ' // &
                         'out of range', '2 <= n'//ax//' <= '//itoa(MAX_CHART_N)// &
                         ' and nx*ny <= '//itoa(MAX_CHART_POINTS))
                return
            end if
        end subroutine chart_axis

    end procedure check_chart

    !> &design (checked when the analysis is requested; its lengths are in deck units):
    !! finite values; 0 < l_min < l_max with l over b' in RATIO_MIN .. RATIO_MAX and
    !! 2 <= nl <= MAX_CHART_N; b kept (b_min = b_max = 0, nb = 1), one b (b_min = b_max > 0,
    !! nb = 1) or 0 < b_min < b_max with 2 <= nb <= MAX_CHART_N, b over b' in range;
    !! 0 < amplitude_max <= 90 degrees, 1 <= n_amplitudes <= MAX_DESIGN_AMPLITUDES, the
    !! smallest amplitude amplitude_max/n_amplitudes >= FLOQUET_AMPLITUDE_MIN; at most
    !! MAX_CHART_POINTS Floquet points; each uncertainty >= 0 and below the value it
    !! qualifies (u_mass < mass, u_l < l_min, u_b below every b and b'; the period is only
    !! known when computed: the analysis checks u_period against it).
    module procedure check_design
        real(dp) :: bmin
        if (stat%code /= STATUS_OK) return
        call positive(stat, 'design', 'l_min', d%design_l_min, '0 < l_min < l_max (deck units)')
        call positive(stat, 'design', 'l_max', d%design_l_max, '0 < l_min < l_max (deck units)')
        if (stat%code /= STATUS_OK) return
        if (d%design_l_min >= d%design_l_max) then
            call bad(stat, 'design', 'l_max', rshort(d%design_l_max), 'not larger than '// &
                     'l_min = '//rshort(d%design_l_min), 'l_min < l_max')
            return
        end if
        call over_b_prime(stat, 'design', 'l_min', d%design_l_min, d%b_prime, RATIO_MIN)
        call over_b_prime(stat, 'design', 'l_max', d%design_l_max, d%b_prime, RATIO_MIN)
        if (stat%code /= STATUS_OK) return
        if (d%design_nl < 2 .or. d%design_nl > MAX_CHART_N) then
            call bad(stat, 'design', 'nl', itoa(d%design_nl), 'number of cable lengths '// &
                     'out of range', '2 <= nl <= '//itoa(MAX_CHART_N))
            return
        end if
        call finite(stat, 'design', 'b_min', d%design_b_min)
        call finite(stat, 'design', 'b_max', d%design_b_max)
        if (stat%code /= STATUS_OK) return
        if (d%design_nb == 1) then
            if (d%design_b_min /= d%design_b_max) then
                call bad(stat, 'design', 'b_max', rshort(d%design_b_max), 'differs from '// &
                         'b_min = '//rshort(d%design_b_min)//' with nb = 1', 'b_min = '// &
                         'b_max = 0 with nb = 1 (the deck''s b), b_min = b_max > 0 with '// &
                         'nb = 1 (that b), or 0 < b_min < b_max with nb >= 2')
                return
            end if
            if (d%design_b_min /= 0.0_dp) call positive(stat, 'design', 'b_min', &
                d%design_b_min, 'b_min = b_max = 0 (the deck''s b) or > 0')
        else if (d%design_nb < 1 .or. d%design_nb > MAX_CHART_N) then
            call bad(stat, 'design', 'nb', itoa(d%design_nb), 'number of support spacings '// &
                     'out of range', '1 <= nb <= '//itoa(MAX_CHART_N))
            return
        else
            call positive(stat, 'design', 'b_min', d%design_b_min, '0 < b_min < b_max '// &
                          'with nb >= 2')
            if (stat%code /= STATUS_OK) return
            if (d%design_b_min >= d%design_b_max) call bad(stat, 'design', 'b_max', &
                rshort(d%design_b_max), 'not larger than b_min = '//rshort(d%design_b_min)// &
                ' with nb = '//itoa(d%design_nb), 'b_min < b_max with nb >= 2')
        end if
        if (stat%code /= STATUS_OK) return
        if (d%design_b_min > 0.0_dp) then
            call over_b_prime(stat, 'design', 'b_min', d%design_b_min, d%b_prime, RATIO_MIN)
            call over_b_prime(stat, 'design', 'b_max', d%design_b_max, d%b_prime, RATIO_MIN)
        end if
        ! the body's spacing b', as b
        call finite(stat, 'design', 'b_prime_min', d%design_b_prime_min)
        call finite(stat, 'design', 'b_prime_max', d%design_b_prime_max)
        if (stat%code /= STATUS_OK) return
        if (d%design_nb_prime == 1) then
            if (d%design_b_prime_min /= d%design_b_prime_max) then
                call bad(stat, 'design', 'b_prime_max', rshort(d%design_b_prime_max), &
                         'differs from b_prime_min = '//rshort(d%design_b_prime_min)// &
                         ' with nb_prime = 1', 'b_prime_min = b_prime_max = 0 with '// &
                         'nb_prime = 1 (the deck''s b_prime), b_prime_min = b_prime_max > 0 '// &
                         'with nb_prime = 1 (that b_prime), or 0 < b_prime_min < b_prime_max '// &
                         'with nb_prime >= 2')
                return
            end if
            if (d%design_b_prime_min /= 0.0_dp) call positive(stat, 'design', 'b_prime_min', &
                d%design_b_prime_min, 'b_prime_min = b_prime_max = 0 (the deck''s b_prime) '// &
                'or > 0')
        else if (d%design_nb_prime < 1 .or. d%design_nb_prime > MAX_CHART_N) then
            call bad(stat, 'design', 'nb_prime', itoa(d%design_nb_prime), 'number of body '// &
                     'spacings out of range', '1 <= nb_prime <= '//itoa(MAX_CHART_N))
            return
        else
            call positive(stat, 'design', 'b_prime_min', d%design_b_prime_min, &
                          '0 < b_prime_min < b_prime_max with nb_prime >= 2')
            if (stat%code /= STATUS_OK) return
            if (d%design_b_prime_min >= d%design_b_prime_max) call bad(stat, 'design', &
                'b_prime_max', rshort(d%design_b_prime_max), 'not larger than b_prime_min = '// &
                rshort(d%design_b_prime_min)//' with nb_prime = '//itoa(d%design_nb_prime), &
                'b_prime_min < b_prime_max with nb_prime >= 2')
        end if
        if (stat%code /= STATUS_OK) return
        if (d%design_b_prime_min > 0.0_dp) then
            call over_b_prime(stat, 'design', 'b_prime_min', d%design_b_prime_min, d%b_prime, &
                              RATIO_MIN)
            call over_b_prime(stat, 'design', 'b_prime_max', d%design_b_prime_max, d%b_prime, &
                              RATIO_MIN)
            if (stat%code /= STATUS_OK) return
            if (d%design_b_prime_min <= 2.0_dp*abs(d%cg_offset)) call bad(stat, 'design', &
                'b_prime_min', rshort(d%design_b_prime_min), 'does not reach past the mass '// &
                'centre''s offset (cg_offset = '//rshort(d%cg_offset)//')', &
                'b_prime_min > 2 |cg_offset|')
        end if
        call finite(stat, 'design', 'amplitude_max', d%design_amplitude_max)
        if (stat%code /= STATUS_OK) return
        if (d%design_amplitude_max <= 0.0_dp .or. d%design_amplitude_max > 90.0_dp) then
            call bad(stat, 'design', 'amplitude_max', rshort(d%design_amplitude_max), &
                     'out of range', '0 < amplitude_max <= 90 (degrees of theta4)')
            return
        end if
        if (d%design_n_amplitudes < 1 .or. d%design_n_amplitudes > MAX_DESIGN_AMPLITUDES) then
            call bad(stat, 'design', 'n_amplitudes', itoa(d%design_n_amplitudes), &
                     'number of amplitudes out of range', '1 <= n_amplitudes <= '// &
                     itoa(MAX_DESIGN_AMPLITUDES))
            return
        end if
        if (d%design_amplitude_measure == PERIOD_UNSET) &
            d%design_amplitude_measure = min(25.0_dp, d%design_amplitude_max)
        call finite(stat, 'design', 'amplitude_measure', d%design_amplitude_measure)
        if (stat%code /= STATUS_OK) return
        if (d%design_amplitude_measure <= 0.0_dp .or. &
            d%design_amplitude_measure > d%design_amplitude_max) then
            call bad(stat, 'design', 'amplitude_measure', rshort(d%design_amplitude_measure), &
                     'out of range', '0 < amplitude_measure <= amplitude_max = '// &
                     rshort(d%design_amplitude_max)//' (degrees of theta4: the amplitude of '// &
                     'the measurement, within the stability checked)')
            return
        end if
        if (d%design_amplitude_max/d%design_n_amplitudes < FLOQUET_AMPLITUDE_MIN) then
            call bad(stat, 'design', 'amplitude_max', rshort(d%design_amplitude_max), &
                     'its smallest amplitude amplitude_max/n_amplitudes is below '// &
                     rshort(FLOQUET_AMPLITUDE_MIN)//' degrees', 'amplitude_max/n_amplitudes'// &
                     ' >= '//rshort(FLOQUET_AMPLITUDE_MIN)//' (degrees of theta4)')
            return
        end if
        if (real(d%design_nl, dp)*d%design_nb*d%design_nb_prime*d%design_n_amplitudes > &
            MAX_CHART_POINTS) then
            call bad(stat, 'design', 'n_amplitudes', itoa(d%design_n_amplitudes), &
                     'too many Floquet points (nl*nb*n_amplitudes = '// &
                     sci(real(d%design_nl, dp)*d%design_nb*d%design_n_amplitudes)//')', &
                     'nl*nb*n_amplitudes <= '//itoa(MAX_CHART_POINTS))
            return
        end if
        bmin = min(d%b_prime, d%b)
        if (d%design_b_min > 0.0_dp) bmin = min(d%b_prime, d%design_b_min)
        call uncertainty('u_mass', d%design_u_mass, d%mass, 'the mass')
        call uncertainty('u_l', d%design_u_l, d%design_l_min, 'l_min')
        call uncertainty('u_b', d%design_u_b, bmin, 'every b and b_prime')
        call uncertainty('u_period', d%design_u_period, huge(1.0_dp), '')

    contains

        !> A standard uncertainty: finite, >= 0, below the value it qualifies.
        subroutine uncertainty(var, u, x, what)
            character(len=*), intent(in) :: var     !! its name
            real(dp), intent(in) :: u, x            !! the uncertainty and its value
            character(len=*), intent(in) :: what    !! the value's name ('' for none)
            character(len=:), allocatable :: allowed
            if (stat%code /= STATUS_OK) return
            call finite(stat, 'design', var, u)
            if (stat%code /= STATUS_OK) return
            allowed = '0 <= '//var
            if (len(what) > 0) allowed = allowed//' < '//what//' ('//rshort(x)//')'
            allowed = allowed//', a standard uncertainty in deck units'
            if (var == 'u_period') allowed = allowed//' (s)'
            if (u < 0.0_dp) then
                call bad(stat, 'design', var, rshort(u), 'a negative uncertainty', allowed)
            else if (len(what) > 0 .and. u >= x) then
                call bad(stat, 'design', var, rshort(u), 'not below the value it qualifies', &
                         allowed)
            end if
        end subroutine uncertainty

    end procedure check_design

    !> ERR_DECK naming the deck, group, variable and value, what is wrong and what is
    !! allowed (nothing when stat already carries an error).
    subroutine bad(stat, grp, var, val, what, allowed)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var, val, what, allowed
        if (stat%code /= STATUS_OK) return
        call set_error(stat, ERR_DECK, '&'//grp//' '//var//' = '//val//': '// &
                       what//'; allowed: '//allowed)
    end subroutine bad

    !> ERR_DECK when the standard uncertainty u of input x puts the 5-sigma range x +- 5 u
    !! outside the input's domain: lo < x - 5 u (lo <= x - 5 u when closed) and, when
    !! hi > lo, x + 5 u < hi.  A Monte Carlo draws its inputs from N(x, u^2) and the budget
    !! steps around x: neither may leave the domain (l < 0, g < 0, an amplitude beyond 180
    !! degrees).  u = 0 and a non-finite x (refused elsewhere) pass.
    subroutine in_domain(stat, grp, uname, u, xname, x, lo, hi, closed)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp         !! the group of u
        character(len=*), intent(in) :: uname, xname    !! the names of u and of its input
        real(dp), intent(in) :: u, x                !! the uncertainty and the input's value
        real(dp), intent(in) :: lo, hi              !! the domain (hi <= lo: no upper bound)
        logical, intent(in), optional :: closed     !! x = lo allowed
        real(dp) :: umax
        character(len=:), allocatable :: dom
        logical :: low_ok, cl
        if (stat%code /= STATUS_OK) return
        if (.not. (u > 0.0_dp) .or. .not. ieee_is_finite(x) .or. .not. ieee_is_finite(u)) &
            return
        cl = .false.
        if (present(closed)) cl = closed
        if (cl) then
            low_ok = x - 5.0_dp*u >= lo
        else
            low_ok = x - 5.0_dp*u > lo
        end if
        if (low_ok .and. (hi <= lo .or. x + 5.0_dp*u < hi)) return
        umax = (x - lo)/5.0_dp
        if (hi > lo) umax = min(umax, (hi - x)/5.0_dp)
        umax = max(0.0_dp, umax)
        dom = xname//trim(merge(' >= ', ' >  ', cl))//' '//rshort(lo)
        if (hi > lo) dom = rshort(lo)//' < '//xname//' < '//rshort(hi)
        call bad(stat, grp, uname, rshort(u), 'the 5-sigma range of '//xname// &
                 ' = '//rshort(x)//' +- 5 '//uname//' reaches '// &
                 rshort(merge(x - 5.0_dp*u, x + 5.0_dp*u, .not. low_ok))//', outside '//dom// &
                 ' (a Monte Carlo would draw such values, the budget step there)', &
                 '0 <= '//uname//' < '//rshort(umax)//' for '//xname//' = '//rshort(x)// &
                 ' (a fifth of the distance to the edge)')
    end subroutine in_domain

    !> ERR_DECK when x is NaN or infinite.
    subroutine finite(stat, grp, var, x)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x
        if (.not. ieee_is_finite(x)) call bad(stat, grp, var, rshort(x), 'not a finite ' &
                                              //'number (NaN, Inf, or beyond 1.8e308)', &
                                              'finite real numbers')
    end subroutine finite

    !> ERR_DECK when the dimensional value x (> 0) lies outside DIM_MIN .. DIM_MAX.
    subroutine dimensional(stat, grp, var, x)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x                   !! a length, g, a mass or a moment (> 0)
        if (stat%code /= STATUS_OK) return          ! x may be NaN
        if (x < DIM_MIN .or. x > DIM_MAX) call bad(stat, grp, var, rshort(x), 'out of ' // &
            'range', rshort(DIM_MIN)//' <= '//var//' <= '//rshort(DIM_MAX)//' in any units')
    end subroutine dimensional

    !> ERR_DECK when |x|/b' (x /= 0, b' > 0, both finite) lies outside lo .. RATIO_MAX
    !! (lo = 0: no lower bound).
    subroutine over_b_prime(stat, grp, var, x, b_prime, lo)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x, b_prime          !! the length (/= 0) and b' (> 0)
        real(dp), intent(in) :: lo                  !! smallest ratio allowed (0: none)
        real(dp) :: lq
        character(len=:), allocatable :: allowed, nm
        if (stat%code /= STATUS_OK) return
        nm = var
        if (x < 0.0_dp .or. var == 'sway_depth') nm = '|'//var//'|'     ! a signed length
        lq = log(abs(x)) - log(b_prime)   ! in logarithms: x/b' itself may overflow
        if (lq <= log(RATIO_MAX)) then
            if (lo <= 0.0_dp) return
            if (lq >= log(lo)) return
        end if
        allowed = nm//'/b_prime <= '//rshort(RATIO_MAX)
        if (lo > 0.0_dp) allowed = rshort(lo)//' <= '//allowed
        call bad(stat, grp, var, rshort(x), nm//'/b_prime = '// &
                 sci(exp(max(-700.0_dp, min(700.0_dp, lq))))//' out of range (b_prime = '// &
                 rshort(b_prime)//')', allowed//' (the geometry in units of b_prime)')
    end subroutine over_b_prime

    !> ERR_DECK when an angle (rad) is beyond ANGLE_MAX in magnitude.
    subroutine angle(stat, grp, var, x)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var
        real(dp), intent(in) :: x                   !! angle, rad (finite)
        if (stat%code /= STATUS_OK) return
        if (abs(x) > ANGLE_MAX) call bad(stat, grp, var, rshort(x), 'an angle beyond '// &
            rshort(ANGLE_MAX)//' rad', '|'//var//'| <= '//rshort(ANGLE_MAX)// &
            ' rad (angles are taken modulo 2 pi)')
    end subroutine angle

    !> The deck's angles (tilt, theta, lambda; |x| <= ANGLE_MAX) reduced modulo 2 pi into
    !! [-pi, pi]: the integrator's error control is relative, so an angle of 1e6 rad would
    !! leave it a tolerance of rtol*1e6 rad.
    module procedure reduce_angles
        d%tilt = reduced(d%tilt)
        d%theta = [reduced(d%theta(1)), reduced(d%theta(2)), reduced(d%theta(3)), &
                   reduced(d%theta(4))]
        d%lambda = reduced(d%lambda)
    end procedure reduce_angles

    !> x - 2 pi n, n the nearest integer to x/(2 pi), with 2 pi split in three parts
    !! (Cody and Waite) so that the result is accurate to roundoff for |x| <= 2**20 * 2 pi;
    !! x itself when |x| <= pi.
    pure real(dp) function reduced(x) result(r)
        real(dp), intent(in) :: x                   !! angle, rad
        real(dp), parameter :: TWO_PI = 6.283185307179586_dp
        ! 2 pi = P1 + P2 + P3: P1 with 33 significant bits (n*P1 exact for n < 2**20), P2 the
        ! rest of the double TWO_PI, P3 = 2 pi - TWO_PI
        real(dp), parameter :: P1 = real(int(TWO_PI*2.0_dp**30, int64), dp)/2.0_dp**30
        real(dp), parameter :: P2 = TWO_PI - P1
        real(dp), parameter :: P3 = 2.4492935982947064e-16_dp
        real(dp) :: n
        r = x
        if (abs(x) <= 0.5_dp*TWO_PI) return
        n = anint(x/TWO_PI)
        r = ((x - n*P1) - n*P2) - n*P3
    end function reduced

    !> ERR_DECK when x is not finite or not > 0.
    subroutine positive(stat, grp, var, x, allowed)
        type(status_t), intent(inout) :: stat       !! the first problem
        character(len=*), intent(in) :: grp, var, allowed
        real(dp), intent(in) :: x
        if (stat%code /= STATUS_OK) return
        call finite(stat, grp, var, x)
        if (stat%code /= STATUS_OK) return
        if (x <= 0.0_dp) call bad(stat, grp, var, rshort(x), 'must be > 0', allowed)
    end subroutine positive

    pure function ortho_allowed() result(s)
        character(len=:), allocatable :: s
        s = 'orthonormal rows within 1e-9 (btilde btilde^T = I) and determinant +1'
    end function ortho_allowed

    !> Check that a string value is one of the blank-separated words of `allowed`.
    subroutine check_word(stat, grp, var, val, allowed)
        type(status_t), intent(inout) :: stat       !! ERR_DECK when val is not allowed
        character(len=*), intent(in) :: grp, var, val, allowed
        if (index(' '//allowed//' ', ' '//lower(trim(adjustl(val)))//' ') > 0 .and. &
            len_trim(val) > 0 .and. index(trim(adjustl(val)), ' ') == 0) return
        call set_error(stat, ERR_DECK, '&'//grp//' '//var//' = '''//clip(trim(val))// &
                       ''': unknown '//var//'; allowed: '//commas(allowed))
    end subroutine check_word

    !> &output columns: blank-separated names from OUTPUT_COLUMNS (any case), at least one,
    !! none twice; `cols` gets them in OUTPUT_COLUMNS' order, with its spelling.
    subroutine check_columns(stat, columns, cols)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: columns     !! value read
        character(len=*), intent(inout) :: cols     !! the columns, in OUTPUT_COLUMNS' order
        character(len=len(columns)) :: list
        character(len=len(OUTPUT_COLUMNS)) :: known
        logical :: asked(count_words(OUTPUT_COLUMNS))
        integer :: i1, i2, j1, j2, n
        character(len=:), allocatable :: head, allowed
        list = columns
        do i1 = 1, len(list)
            if (list(i1:i1) == achar(9)) list(i1:i1) = ' '
        end do
        known = lower(OUTPUT_COLUMNS)
        head = '&output columns = '''//trim(adjustl(list))//''': '
        allowed = 'allowed: blank-separated names, in any order and case, from: '// &
            commas(OUTPUT_COLUMNS)
        asked = .false.
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            j2 = 0
            n = 0
            do
                call next_word(known, j2, j1)
                if (j1 == 0) exit
                n = n + 1
                if (known(j1:j2) == lower(list(i1:i2))) exit
            end do
            if (j1 == 0) then
                call set_error(stat, ERR_DECK, head//'unknown column '''//list(i1:i2)// &
                               '''; '//allowed)
                return
            end if
            if (asked(n)) then
                call set_error(stat, ERR_DECK, head//'column '''//list(i1:i2)// &
                               ''' given twice; '//allowed)
                return
            end if
            asked(n) = .true.
        end do
        if (.not. any(asked)) then
            call set_error(stat, ERR_DECK, head//'no column given; '//allowed)
            return
        end if
        cols = ''
        j2 = 0
        n = 0
        do
            call next_word(OUTPUT_COLUMNS, j2, j1)
            if (j1 == 0) exit
            n = n + 1
            if (asked(n)) cols = trim(cols)//' '//OUTPUT_COLUMNS(j1:j2)
        end do
        cols = adjustl(cols)
    end subroutine check_columns

    !> Every word of &scene analyses must be known; at least one word.
    subroutine check_analyses(stat, analyses)
        type(status_t), intent(inout) :: stat       !! ERR_DECK on a problem
        character(len=*), intent(in) :: analyses    !! value read
        character(len=len(analyses)) :: list
        integer :: i1, i2
        character(len=:), allocatable :: head
        list = lower(analyses)
        head = '&scene analyses = '''//clip(trim(analyses))//''': '
        if (len_trim(list) > 256) then
            call set_error(stat, ERR_DECK, head//'longer than 256 characters; allowed: '// &
                           'blank-separated words from: '//commas(ANALYSES_ALLOWED))
            return
        end if
        if (len_trim(list) == 0) then
            call set_error(stat, ERR_DECK, head//'no analysis given; allowed: '// &
                           'blank-separated words from: '//commas(ANALYSES_ALLOWED))
            return
        end if
        i2 = 0
        do
            call next_word(list, i2, i1)
            if (i1 == 0) exit
            if (index(' '//ANALYSES_ALLOWED//' ', ' '//list(i1:i2)//' ') == 0) then
                call set_error(stat, ERR_DECK, head//'unknown analysis '''// &
                               analyses(i1:i2)//'''; allowed: blank-separated words from: '// &
                               commas(ANALYSES_ALLOWED))
                return
            end if
        end do
    end subroutine check_analyses

    function btilde_short(bt) result(s)
        real(dp), intent(in) :: bt(3,3)             !! btilde
        character(len=:), allocatable :: s
        s = '['//rlist_short(bt(1, :))//'; '//rlist_short(bt(2, :))//'; '// &
            rlist_short(bt(3, :))//']'
    end function btilde_short


    module procedure check_measuring
        character(len=:), allocatable :: what, missing
        if (stat%code /= STATUS_OK) return
        what = ''
        if (analysis_requested(d, 'identify')) what = 'identify'
        if (analysis_requested(d, 'tensor')) what = 'tensor'
        if (analysis_requested(d, 'design')) what = 'design'
        if (d%cables > 2 .and. (what /= 'identify' .or. count_words(d%analyses) > 1)) then
            call bad(stat, 'suspension', 'cables', itoa(d%cables), 'a platform of '// &
                     itoa(d%cables)//' cables with analyses = '''//trim(d%analyses)//'''', &
                     'cables >= 3 with analyses = ''identify'' alone (its torsion is exact); '// &
                     'every other analysis models two cables')
            return
        end if
        if (len(what) == 0) return
        missing = ''
        call need('&suspension g', deck_gave(d, 'g'))
        call need('&body mass', deck_gave(d, 'mass'))
        call need('&suspension l', deck_gave(d, 'l'))
        if (d%cables == 2) then
            call need('&suspension l_prime', deck_gave(d, 'l_prime'))
            call need('&suspension b', deck_gave(d, 'b'))
            call need('&suspension b_prime', deck_gave(d, 'b_prime'))
            ! (a tensor deck's mass centre may come from its table of hangs: checked there)
            if (what /= 'tensor') &
                call need('&body the mass centre (cg_depth and cg_offset, or r and lambda)', &
                          deck_gave(d, 'cg_depth') .or. (deck_gave(d, 'r') .and. &
                          deck_gave(d, 'lambda')))
        else
            call need('&suspension radius', deck_gave(d, 'radius'))
            call need('&suspension radius_prime', deck_gave(d, 'radius_prime'))
        end if
        if (len(missing) > 0) call set_error(stat, ERR_DECK, 'not given: '//missing// &
            '; a deck with analyses = '''//what//''' gives every physical input itself (the '// &
            'defaults are the paper''s dimensionless scene); allowed: g, mass, l, l_prime, '// &
            'b and b_prime (the full distances between the two cables on the support and on '// &
            'the body) in one system of units, and the mass centre')
    contains
        subroutine need(name, given)
            character(len=*), intent(in) :: name
            logical, intent(in) :: given
            if (given) return
            if (len(missing) > 0) missing = missing//', '
            missing = missing//name
        end subroutine need
    end procedure check_measuring


    module procedure check_tensor
        integer :: i
        character(len=*), parameter :: UNAMES(8) = [character(len=11) :: 'u_mass', 'u_l', &
            'u_l_prime', 'u_b', 'u_b_prime', 'u_g', 'u_period', 'u_amplitude']
        character(len=*), parameter :: XNAMES(6) = [character(len=7) :: 'mass', 'l', &
            'l_prime', 'b', 'b_prime', 'g']
        real(dp) :: xv(6)
        if (stat%code /= STATUS_OK) return
        xv = [d%mass, d%l, d%l_prime, d%b, d%b_prime, d%g]
        do i = 1, size(d%tensor_u)
            call finite(stat, 'tensor', trim(UNAMES(i)), d%tensor_u(i))
            if (stat%code /= STATUS_OK) return
            if (d%tensor_u(i) < 0.0_dp .or. d%tensor_u(i) > DIM_MAX) call bad(stat, 'tensor', &
                trim(UNAMES(i)), rshort(d%tensor_u(i)), 'a standard uncertainty out of range', &
                '0 <= '//trim(UNAMES(i))//' <= '//rshort(DIM_MAX)//' (deck units; 0: not known)')
        end do
        if (stat%code /= STATUS_OK) return
        ! the 5-sigma range of each input inside its domain (check_measurement's rule); the
        ! periods and amplitudes are the table's, checked with it
        do i = 1, 6
            call in_domain(stat, 'tensor', trim(UNAMES(i)), d%tensor_u(i), trim(XNAMES(i)), &
                           xv(i), 0.0_dp, 0.0_dp)
        end do
        call finite(stat, 'tensor', 'u_direction', d%tensor_u_direction)
        if (stat%code /= STATUS_OK) return
        if (d%tensor_u_direction < 0.0_dp .or. d%tensor_u_direction > 30.0_dp) &
            call bad(stat, 'tensor', 'u_direction', rshort(d%tensor_u_direction), &
                     'a standard uncertainty of a direction out of range', '0 <= u_direction '// &
                     '<= 30 (degrees)')
        do i = 1, 3
            call finite(stat, 'tensor', 'cg', d%tensor_cg(i))
        end do
        if (stat%code /= STATUS_OK) return
        if (d%tensor_monte_carlo == 1 .or. d%tensor_monte_carlo < 0 .or. &
            d%tensor_monte_carlo > MAX_MONTE_CARLO) call bad(stat, 'tensor', 'monte_carlo', &
            itoa(d%tensor_monte_carlo), 'number of Monte Carlo samples out of range', &
            '0 (first order only) or 2 <= monte_carlo <= '//itoa(MAX_MONTE_CARLO))
        if (stat%code /= STATUS_OK) return
        if (d%tensor_plan /= 0 .and. (d%tensor_plan < 6 .or. d%tensor_plan > 26)) &
            call bad(stat, 'tensor', 'plan', itoa(d%tensor_plan), 'number of hangs to plan '// &
                     'out of range', '0 (no plan) or 6 <= plan <= 26 (the face, edge and '// &
                     'corner directions of the body frame)')
        if (stat%code /= STATUS_OK) return
        if (analysis_requested(d, 'tensor') .and. len_trim(d%tensor_hangs) == 0 .and. &
            d%tensor_plan == 0) call bad(stat, 'tensor', 'hangs', '''''', 'no table of hangs', &
            'hangs = ''FILE'' (a table, relative to the deck''s folder), or plan = N to '// &
            'plan N hangs')
    end procedure check_tensor

end submodule deck_checks
