!> The rig layer: a physical rig (suspension, body, damping, cables) and how it starts to
!! move, in the deck's units, between the deck's groups and the analyses.
!!
!! An analysis builds its rig once from the deck's groups (rig_of, start_of: module
!! rig_groups) and varies the rig_t, never a copy of the deck: a trial I1 of a fit, a
!! candidate suspension of a design, an input of an uncertainty budget are changes of a
!! rig_t.  The model sees the rig scaled (make_pendulum: lengths over b', moments over
!! m b'^2, time tau = sqrt(g/b') t) and starts from start_state.
module rig
    use kinds, only: dp, deg
    use status, only: status_t, set_error, ERR_DECK
    use text, only: sci
    use rig_groups, only: suspension_group_t, body_group_t, damping_group_t, &
        cables_group_t, start_group_t, integration_group_t, DEFAULT_RTOL, DEFAULT_ATOL, &
        DEFAULT_SENS_ERROR_CONTROL
    use geometry, only: pendulum_t, beta_coeffs
    use start_pose, only: raised_angles, solve_theta5
    use bifilar_model, only: chart_state, NSTATE
    use integrators, only: integrator_for, SOLVER_LSODA, SENS_FORWARD, sensitivities_for
    use rig_type, only: rig_t, start_t
    implicit none
    private

    !> The rig and its start (module rig_type's types, which the measurement's model
    !! holds below this layer's runs).
    public :: rig_t, start_t

    !> How accurately a rig's runs are integrated: &integration rtol, atol, the integrator
    !! and how derivatives of runs are taken (module integrators).
    type, public :: accuracy_t
        real(dp) :: rtol = DEFAULT_RTOL, atol = DEFAULT_ATOL
        integer :: method = SOLVER_LSODA
        integer :: sensitivities = SENS_FORWARD     !! SENS_FORWARD or SENS_DIFFERENCES
        !> forward sensitivities in the integrator's error test (&integration
        !! sensitivity_error_control)
        logical :: sens_error_control = DEFAULT_SENS_ERROR_CONTROL
    end type accuracy_t

    !> The rig of the deck's &suspension, &body, &damping and &cables (module deck_runs adds
    !! rig_of(deck)); likewise start_of (&start), method_of and accuracy_of (&integration
    !! with &scene model), output_times (&integration).
    interface rig_of
        module procedure rig_of_groups
    end interface rig_of
    interface start_of
        module procedure start_of_group
    end interface start_of
    interface method_of
        module procedure method_of_group
    end interface method_of
    interface accuracy_of
        module procedure accuracy_of_group
    end interface accuracy_of
    interface output_times
        module procedure output_times_group
    end interface output_times

    public :: rig_of, start_of, raised_start, method_of, accuracy_of, make_pendulum
    public :: start_state, move_b_prime, output_times
    public :: same_rig, same_start

contains

    !> The rig of the deck's groups (&suspension and &body normalised: a platform's
    !! equivalent pair, the mass centre as r, lambda).
    pure function rig_of_groups(sus, bod, dmp, cab) result(rg)
        type(suspension_group_t), intent(in) :: sus
        type(body_group_t), intent(in) :: bod
        type(damping_group_t), intent(in) :: dmp
        type(cables_group_t), intent(in) :: cab
        type(rig_t) :: rg
        rg%b = sus%b
        rg%b_prime = sus%b_prime
        rg%l = sus%l
        rg%l_prime = sus%l_prime
        rg%g = sus%g
        rg%mass = bod%mass
        rg%inertia = bod%inertia
        rg%r = bod%r
        rg%lambda = bod%lambda
        rg%btilde = bod%btilde
        rg%sway_depth = bod%sway_depth
        rg%c_v = dmp%c_v
        rg%c_q = dmp%c_q
        rg%cable_stiffness = cab%stiffness
        rg%cable_damping = cab%damping
        rg%cables = sus%cables
        if (sus%cables > 2) rg%cg_offset_y = bod%cg_offset_y
    end function rig_of_groups

    !> The start of &start (normalised).
    pure function start_of_group(sta) result(st)
        type(start_group_t), intent(in) :: sta
        type(start_t) :: st
        st%mode = trim(sta%mode)
        st%amplitude = sta%amplitude
        st%tilt = sta%tilt
        st%theta = sta%theta
        st%theta_dot = sta%theta_dot
    end function start_of_group

    !> The paper's raised start at `amplitude` degrees, no tilt: a release at rest.
    pure function raised_start(amplitude) result(st)
        real(dp), intent(in) :: amplitude       !! degrees of theta_4
        type(start_t) :: st
        st%mode = 'raised'
        st%amplitude = amplitude
    end function raised_start

    !> The integrator of a deck's runs (module integrators: &integration method, &scene
    !! model).
    pure integer function method_of_group(integ, model)
        type(integration_group_t), intent(in) :: integ
        character(len=*), intent(in) :: model   !! &scene model ('kane', 'elastic')
        method_of_group = integrator_for(integ%method, model)
    end function method_of_group

    !> The accuracy of a deck's runs (&integration rtol, atol, method, sensitivities, with
    !! &scene model).
    pure function accuracy_of_group(integ, model) result(acc)
        type(integration_group_t), intent(in) :: integ
        character(len=*), intent(in) :: model   !! &scene model ('kane', 'elastic')
        type(accuracy_t) :: acc
        acc%rtol = integ%rtol
        acc%atol = integ%atol
        acc%method = method_of_group(integ, model)
        acc%sensitivities = sensitivities_for(integ%sensitivities)
        acc%sens_error_control = integ%sensitivity_error_control
    end function accuracy_of_group

    !> Scaled pendulum parameters of a rig (lengths over b', inertia over m b'^2, damping in
    !! the model's units), with the geometric check a deck reader cannot make: the cables
    !! must be able to reach.
    subroutine make_pendulum(rg, p, stat)
        type(rig_t), intent(in) :: rg           !! the rig
        type(pendulum_t), intent(out) :: p      !! scaled parameters
        type(status_t), intent(out) :: stat     !! ERR_DECK when the geometry is impossible
        p%big_l = rg%l/rg%b_prime
        p%big_lp = rg%l_prime/rg%b_prime
        p%big_b = rg%b/rg%b_prime
        p%inertia = rg%inertia/(rg%mass*rg%b_prime**2)
        p%r = rg%r/rg%b_prime
        p%lambda = rg%lambda
        p%btilde = rg%btilde
        p%h_e = rg%sway_depth/rg%b_prime
        ! &damping in the model's units: torque over m g b', rates per unit tau
        p%c_v = rg%c_v/(rg%mass*rg%b_prime*sqrt(rg%g*rg%b_prime))
        p%c_q = rg%c_q/(rg%mass*rg%b_prime**2)
        p%stab_rate = 1.0_dp     ! Baumgarte rate: constraint drift decays in about one tau
        if (rg%b >= rg%l + rg%l_prime + rg%b_prime .or. &
            rg%b_prime >= rg%l + rg%l_prime + rg%b) then
            call set_error(stat, ERR_DECK, '&suspension b = '//sci(rg%b)//', b_prime = '// &
                sci(rg%b_prime)//', l = '//sci(rg%l)//', l_prime = '//sci(rg%l_prime)// &
                ': the cables cannot reach; allowed: b < l + l_prime + b_prime and '// &
                'b_prime < l + l_prime + b')
        end if
    end subroutine make_pendulum

    !> The start as a chart state: mode 'raised' (the paper's recipe, tilt added to theta_1,
    !! theta_5 from eq. (2) by the homotopy of eq. (44)) or mode 'angles' (theta_1..4 and
    !! their rates given; theta_5 from eq. (2), its rate from eq. (5)).
    subroutine start_state(st, p, y0, th0, stat)
        type(start_t), intent(in) :: st         !! how the rig starts
        type(pendulum_t), intent(in) :: p       !! scaled parameters (make_pendulum)
        real(dp), intent(out) :: y0(NSTATE)     !! chart state at tau = 0
        real(dp), intent(out) :: th0(5)         !! theta_1..5 at tau = 0
        type(status_t), intent(out) :: stat     !! ERR_DECK when no start satisfies eq. (2)
        real(dp) :: thd(5), beta(5)
        character(len=40) :: what
        thd = 0.0_dp
        y0 = 0.0_dp
        if (trim(st%mode) == 'raised') then
            call raised_angles(p, st%amplitude*deg, th0, stat)
            what = '&start mode = ''raised'''
            if (stat%code /= 0) then
                return
            end if
            th0(1) = th0(1) + st%tilt
        else
            th0 = [st%theta, 0.0_dp]
            thd(1:4) = st%theta_dot
            what = '&start theta'
        end if
        call solve_theta5(p, th0, stat)
        if (stat%code /= 0) then
            stat%msg = trim(what)//': '//stat%msg
            return
        end if
        beta = beta_coeffs(p, th0)
        if (.not. (abs(beta(5)) > 1.0e-10_dp)) then
            call set_error(stat, ERR_DECK, trim(what)// &
                ': beta5 = 0 at the start, eq. (5) cannot give theta5_dot; allowed: a start '// &
                'with line CD not vertical (change theta or the rates)')
            return
        end if
        thd(5) = sum(beta(1:4)*thd(1:4))/beta(5)
        y0 = chart_state(th0, thd)
    end subroutine start_state

    !> Two rigs are the same, value for value (every component of rig_t: keep in step).
    pure logical function same_rig(a, b)
        type(rig_t), intent(in) :: a, b
        same_rig = a%b == b%b .and. a%b_prime == b%b_prime .and. a%l == b%l .and. &
                   a%l_prime == b%l_prime .and. a%g == b%g .and. a%mass == b%mass .and. &
                   all(a%inertia == b%inertia) .and. a%r == b%r .and. a%lambda == b%lambda .and. &
                   all(a%btilde == b%btilde) .and. a%sway_depth == b%sway_depth .and. &
                   a%c_v == b%c_v .and. a%c_q == b%c_q .and. &
                   a%cable_stiffness == b%cable_stiffness .and. &
                   a%cable_damping == b%cable_damping .and. a%cables == b%cables .and. &
                   a%cg_offset_y == b%cg_offset_y
    end function same_rig

    !> Two starts are the same, value for value (every component of start_t: keep in step).
    pure logical function same_start(a, b)
        type(start_t), intent(in) :: a, b
        same_start = a%mode == b%mode .and. a%amplitude == b%amplitude .and. &
                     a%tilt == b%tilt .and. all(a%theta == b%theta) .and. &
                     all(a%theta_dot == b%theta_dot)
    end function same_start

    !> The rig with the body's spacing b' changed to bp: the two body attachment points move
    !! symmetrically, so the mass centre keeps its depth below, and its offset along, the
    !! midpoint of CD (r and lambda follow, eq. (21)).
    pure subroutine move_b_prime(rg, bp)
        type(rig_t), intent(inout) :: rg        !! rig to change
        real(dp), intent(in) :: bp              !! new b'
        real(dp) :: depth, along
        depth = rg%r*sin(rg%lambda)
        along = rg%r*cos(rg%lambda) - 0.5_dp*rg%b_prime + 0.5_dp*bp
        rg%b_prime = bp
        rg%r = sqrt(depth**2 + along**2)
        rg%lambda = atan2(depth, along)
    end subroutine move_b_prime

    !> The uniform output grid of a deck's run: tau_k = min(k dtau_out, tau_end),
    !! k = 0 .. nout (&integration).
    pure subroutine output_times_group(integ, times)
        type(integration_group_t), intent(in) :: integ
        real(dp), allocatable, intent(out) :: times(:)  !! (0:nout)
        integer :: nout, k
        nout = nint(integ%tau_end/integ%dtau_out)
        if (nout*integ%dtau_out < integ%tau_end*(1.0_dp - 1.0e-12_dp)) nout = nout + 1
        allocate (times(0:nout))
        do k = 0, nout
            times(k) = min(k*integ%dtau_out, integ%tau_end)
        end do
    end subroutine output_times_group

end module rig
