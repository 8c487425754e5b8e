!> One simulation of a deck: start position, integration by LSODA, output rows and summary.
!!
!! Writes `OUTDIR/NAME.dat` (header, then one row per output time) and `OUTDIR/NAME.summary`
!! (`key = value` lines), each through a temporary file renamed when complete, so a failed
!! run leaves no partial file behind.
module simulate
    use kinds, only: dp, deg
    use status, only: status_t, set_error, ERR_DECK, ERR_MODEL, ERR_NUMERIC
    use geometry, only: pendulum_t, raised_angles, solve_theta5, beta_coeffs
    use bifilar_model, only: bifilar_t, motion_t, chart_state, evaluate, NSTATE
    use lsoda, only: lsoda_t, lsoda_stats_t
    use deck, only: deck_t, deck_echo
    use output_io, only: atomic_open, atomic_commit, atomic_abort, write_kv, all_finite
    implicit none
    private

    !> Figures of one run, also written to the summary file.
    type, public :: run_summary_t
        real(dp) :: cpu_seconds = 0.0_dp
        integer :: steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, method_switches = 0
        integer :: rows = 0
        real(dp) :: max_abs_theta1 = 0.0_dp, max_abs_theta4 = 0.0_dp, max_q = 0.0_dp
        real(dp) :: max_q_axis = 0.0_dp
        real(dp) :: max_abs_energy_error = 0.0_dp, max_abs_constraint_residual = 0.0_dp
        real(dp) :: min_tension = huge(1.0_dp)
        real(dp) :: tau_reached = 0.0_dp
    end type run_summary_t

    public :: make_pendulum, start_state, run_simulation

    character(len=*), parameter :: COLUMNS = '# tau theta1 theta2 theta3 theta4 theta5 '// &
        'theta1_dot theta2_dot theta3_dot theta4_dot theta5_dot Q Q_axis T_BC T_AD '// &
        'energy_error constraint_residual'

contains

    !> Scaled pendulum parameters from a deck (lengths over b', inertia over m b'^2), with the
    !! geometric checks a deck reader cannot make: the cables must be able to reach.
    subroutine make_pendulum(d, p, stat)
        type(deck_t), intent(in) :: d           !! the deck
        type(pendulum_t), intent(out) :: p      !! scaled parameters
        type(status_t), intent(out) :: stat     !! ERR_DECK when the geometry is impossible
        character(len=300) :: buf
        p%big_l = d%l/d%b_prime
        p%big_lp = d%l_prime/d%b_prime
        p%big_b = d%b/d%b_prime
        p%inertia = d%inertia/(d%mass*d%b_prime**2)
        p%r = d%r/d%b_prime
        p%lambda = d%lambda
        p%btilde = d%btilde
        p%h_e = d%sway_depth/d%b_prime
        p%stab_rate = 1.0_dp     ! Baumgarte rate: constraint drift decays in about one tau
        if (d%b >= d%l + d%l_prime + d%b_prime .or. d%b_prime >= d%l + d%l_prime + d%b) then
            write (buf, '(a,4(es10.3,a))') d%name//': &suspension b = ', d%b, ', b_prime = ', &
                d%b_prime, ', l = ', d%l, ', l_prime = ', d%l_prime, &
                ': the cables cannot reach (need b < l + l_prime + b_prime and '// &
                'b_prime < l + l_prime + b)'
            call set_error(stat, ERR_DECK, trim(buf))
        end if
    end subroutine make_pendulum

    !> The start of a deck as a chart state: mode 'raised' (the paper's recipe, tilt added to
    !! theta_1, theta_5 from eq. (2) by the homotopy of eq. (44)) or mode 'angles'
    !! (theta_1..4 and their rates given; theta_5 from eq. (2), its rate from eq. (5)).
    subroutine start_state(d, p, y0, th0, stat)
        type(deck_t), intent(in) :: d           !! the deck
        type(pendulum_t), intent(in) :: p       !! scaled parameters
        real(dp), intent(out) :: y0(NSTATE)     !! chart state at tau = 0
        real(dp), intent(out) :: th0(5)         !! theta_1..5 at tau = 0
        type(status_t), intent(out) :: stat     !! ERR_DECK when no start satisfies eq. (2)
        real(dp) :: thd(5), beta(5)
        character(len=40) :: what
        thd = 0.0_dp
        y0 = 0.0_dp
        if (trim(d%mode) == 'raised') then
            call raised_angles(p, d%amplitude*deg, th0, stat)
            what = '&start mode = ''raised'''
            if (stat%code /= 0) then
                stat%msg = d%name//': '//stat%msg
                return
            end if
            th0(1) = th0(1) + d%tilt
        else
            th0 = [d%theta, 0.0_dp]
            thd(1:4) = d%theta_dot
            what = '&start theta'
        end if
        call solve_theta5(p, th0, stat)
        if (stat%code /= 0) then
            stat%msg = d%name//': '//trim(what)//': '//stat%msg
            return
        end if
        beta = beta_coeffs(p, th0)
        if (.not. (abs(beta(5)) > 1.0e-10_dp)) then
            call set_error(stat, ERR_DECK, d%name//': '//trim(what)// &
                ': beta5 = 0 at the start, eq. (5) cannot give theta5_dot; change the start')
            return
        end if
        thd(5) = sum(beta(1:4)*thd(1:4))/beta(5)
        y0 = chart_state(th0, thd)
    end subroutine start_state

    !> Run the simulation of a deck and write OUTDIR/NAME.dat and OUTDIR/NAME.summary.
    subroutine run_simulation(d, outdir, sm, stat)
        type(deck_t), intent(in) :: d           !! the deck
        character(len=*), intent(in) :: outdir  !! output directory
        type(run_summary_t), intent(out) :: sm  !! figures of the run
        type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_NUMERIC, ERR_MODEL or ERR_IO
        type(bifilar_t) :: sys
        type(lsoda_t) :: solver
        type(lsoda_stats_t) :: st
        type(motion_t) :: mo
        type(status_t) :: wst
        real(dp) :: y(NSTATE), th0(5), tau, e0, th3, row(17), t_cpu0, t_cpu1
        character(len=:), allocatable :: datpath, sumpath
        integer :: u, k, nout
        character(len=300) :: buf

        call make_pendulum(d, sys%p, stat)
        if (stat%code /= 0) return
        call start_state(d, sys%p, y, th0, stat)
        if (stat%code /= 0) return

        datpath = outdir//'/'//d%name//'.dat'
        sumpath = outdir//'/'//d%name//'.summary'
        call atomic_open(datpath, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)') '# bifilar: '//trim(d%title)
        write (u, '(a)') '# time tau = sqrt(g/b'') t; lengths over b''; tensions over m g; '// &
            'energy over m g b''; angles in rad'
        call deck_echo(d, u)
        write (u, '(a)') COLUMNS

        call cpu_time(t_cpu0)
        call solver%init(sys, 0.0_dp, y, d%rtol, [d%atol], stat)
        if (stat%code /= 0) then
            call atomic_abort(u, datpath)
            return
        end if
        nout = nint(d%tau_end/d%dtau_out)
        if (nout*d%dtau_out < d%tau_end*(1.0_dp - 1.0e-12_dp)) nout = nout + 1
        th3 = th0(3)
        e0 = 0.0_dp
        do k = 0, nout
            tau = min(k*d%dtau_out, d%tau_end)
            if (k > 0) then
                call solver%integrate(sys, tau, y, stat)
                if (stat%code /= 0) exit
            end if
            call evaluate(sys%p, y, th3, mo, stat)
            if (stat%code /= 0) then
                write (buf, '(a,f0.4)') ' at tau = ', tau
                stat%msg = stat%msg//trim(buf)
                exit
            end if
            th3 = mo%th(3)
            if (k == 0) e0 = mo%energy
            row = [tau, mo%th, mo%thd, mo%q_sway, mo%q_axis, mo%t_bc, mo%t_ad, &
                   mo%energy - e0, mo%residual]
            if (.not. all_finite(row)) then
                write (buf, '(a,f0.4,a)') 'non-finite result at tau = ', tau, &
                    ': the motion left the range the model covers'
                call set_error(stat, ERR_NUMERIC, trim(buf))
                exit
            end if
            if (min(mo%t_bc, mo%t_ad) <= 0.0_dp) then
                write (buf, '(a,f0.4,a,es10.3,a,es10.3,a)') 'cable goes slack at tau = ', tau, &
                    ' (T_BC = ', mo%t_bc, ', T_AD = ', mo%t_ad, ' m g): the taut-cable model '// &
                    'no longer holds; lower the amplitude or start speed, or lengthen the cables'
                call set_error(stat, ERR_MODEL, trim(buf))
                exit
            end if
            write (u, '(f14.6,16es24.15e3)') row
            sm%rows = sm%rows + 1
            sm%tau_reached = tau
            sm%max_abs_theta1 = max(sm%max_abs_theta1, abs(mo%th(1)))
            sm%max_abs_theta4 = max(sm%max_abs_theta4, abs(mo%th(4)))
            sm%max_q = max(sm%max_q, mo%q_sway)
            sm%max_q_axis = max(sm%max_q_axis, mo%q_axis)
            sm%max_abs_energy_error = max(sm%max_abs_energy_error, abs(mo%energy - e0))
            sm%max_abs_constraint_residual = max(sm%max_abs_constraint_residual, abs(mo%residual))
            sm%min_tension = min(sm%min_tension, mo%t_bc, mo%t_ad)
        end do
        call cpu_time(t_cpu1)
        st = solver%stats()
        sm%cpu_seconds = t_cpu1 - t_cpu0
        sm%steps = st%steps
        sm%rhs_evaluations = st%rhs_evals
        sm%jacobian_evaluations = st%jac_evals
        sm%method_switches = st%method_switches
        if (stat%code /= 0) then
            call atomic_abort(u, datpath)
            if (index(stat%msg, d%name) == 0) stat%msg = d%name//': '//stat%msg
            return
        end if
        call atomic_commit(u, datpath, stat)
        if (stat%code /= 0) return

        call atomic_open(sumpath, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)') '# bifilar summary: '//trim(d%title)
        call write_kv(u, 'deck', d%path)
        call write_kv(u, 'cpu_seconds', sm%cpu_seconds)
        call write_kv(u, 'steps', sm%steps)
        call write_kv(u, 'rhs_evaluations', sm%rhs_evaluations)
        call write_kv(u, 'jacobian_evaluations', sm%jacobian_evaluations)
        call write_kv(u, 'method_switches', sm%method_switches)
        call write_kv(u, 'rows', sm%rows)
        call write_kv(u, 'tau_end', sm%tau_reached)
        call write_kv(u, 'max_abs_theta1', sm%max_abs_theta1)
        call write_kv(u, 'max_abs_theta4', sm%max_abs_theta4)
        call write_kv(u, 'max_Q', sm%max_q)
        call write_kv(u, 'max_Q_axis', sm%max_q_axis)
        call write_kv(u, 'max_abs_energy_error', sm%max_abs_energy_error)
        call write_kv(u, 'max_abs_constraint_residual', sm%max_abs_constraint_residual)
        call write_kv(u, 'min_tension', sm%min_tension)
        call atomic_commit(u, sumpath, wst)
        stat = wst
    end subroutine run_simulation

end module simulate
