!> Tests of the work-precision analysis and the run's error estimate.
module test_work_precision
    use kinds, only: dp
    use status, only: status_t
    use testing, only: tester_t, write_text, fresh_dir
    use output_io, only: read_kv
    use deck, only: deck_t, read_deck
    use work_precision, only: run_work_precision, wp_result_t, WP_NRTOL, WP_NRK4
    implicit none
    private

    public :: run_work_precision_tests

    character(len=*), parameter :: SCRATCH = 'build/test_work_precision'

contains

    subroutine run_work_precision_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call fresh_dir(SCRATCH)
        if (t%want('work_precision: reference, curves, RK4 order, files')) call test_curves(t)
        if (t%want('work_precision: end to end and the error_estimate keys')) &
            call test_end_to_end(t, exe)
        if (t%want('work_precision: the elastic-cable model')) call test_elastic_curves(t)
    end subroutine run_work_precision_tests

    !> input/work_precision_elastic.nml (k = 1e6, zeta = 0.01, tau = 0 ... 3): the reference
    !! (Radau 1e-13 in the generalized coordinates) agrees with RK4 + Richardson and with
    !! LSODA 1e-13 in the maximal coordinates to 1e-9; Radau finishes at every rtol and its
    !! angle error stays within 30 rtol, with fewer steps than LSODA at every rtol
    !! <= 1e-6; LSODA finishes at every rtol the stretch resolves (<= 1e-4) and its error falls
    !! from 1e-4 to 1e-12 by more than 1e5, but lies at 1e2 ... 1e4 rtol for rtol <= 1e-8
    !! (the energy-norm tolerances of the maximal coordinates); every RK4 point run is stable
    !! and as accurate as the reference's confirmation.
    subroutine test_elastic_curves(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(status_t) :: st
        type(wp_result_t) :: res
        integer :: i
        logical :: ok, fewer
        call read_deck('input/work_precision_elastic.nml', d, st)
        call t%check('wp elastic: deck reads', st%code == 0)
        if (st%code /= 0) return
        call run_work_precision(d, SCRATCH, res, st, quiet=.true.)
        call t%check('wp elastic: analysis runs', st%code == 0)
        if (st%code /= 0) return
        write (*, '(a,4es10.2)') '  reference against RK4 + Richardson, LSODA 1e-13 '// &
            '(angles, Q): ', res%ref_agreement_theta, res%ref_agreement_q, &
            res%ref_second_theta, res%ref_second_q
        call t%check('wp elastic: reference = RK4 + Richardson to 1e-9', &
                     res%ref_agreement_theta >= 0.0_dp .and. res%ref_agreement_theta < 1.0e-9_dp &
                     .and. res%ref_agreement_q < 1.0e-9_dp)
        call t%check('wp elastic: reference = LSODA 1e-13 to 1e-9', &
                     res%ref_second_theta >= 0.0_dp .and. res%ref_second_theta < 1.0e-9_dp &
                     .and. res%ref_second_q < 1.0e-9_dp)
        call t%check('wp elastic: Radau finishes at every rtol', all(res%radau%ok))
        call t%check('wp elastic: LSODA finishes at every rtol <= 1e-4', &
                     all(res%lsoda(2:)%ok))
        call t%check('wp elastic: LSODA''s error falls by > 1e5 from rtol 1e-4 to 1e-12', &
                     res%lsoda(WP_NRTOL)%error_theta < 1.0e-5_dp*res%lsoda(2)%error_theta)
        ok = .true.
        fewer = .true.
        do i = 1, WP_NRTOL
            ok = ok .and. res%radau(i)%error_theta <= 30*res%radau(i)%rtol .and. &
                 res%radau(i)%error_q <= 30*res%radau(i)%rtol
            if (res%lsoda(i)%rtol < 1.0e-5_dp) fewer = fewer .and. &
                res%radau(i)%steps < res%lsoda(i)%steps
            write (*, '(a,es8.1,a,es10.2,a,es10.2,a)') '  rtol ', res%radau(i)%rtol, &
                ': angle error Radau ', res%radau(i)%error_theta/res%radau(i)%rtol, &
                ' rtol, LSODA ', res%lsoda(i)%error_theta/res%lsoda(i)%rtol, ' rtol'
        end do
        call t%check('wp elastic: Radau''s errors within 30 rtol at every rtol', ok)
        call t%check('wp elastic: Radau takes fewer steps than LSODA at rtol <= 1e-6', fewer)
        ok = .true.
        do i = 1, WP_NRTOL
            if (res%lsoda(i)%rtol > 1.0e-8_dp*(1 + 1.0e-9_dp)) cycle
            ok = ok .and. res%lsoda(i)%error_theta < 1.0e4_dp*res%lsoda(i)%rtol
        end do
        call t%check('wp elastic: LSODA''s angle error < 1e4 rtol for rtol <= 1e-8', ok)
        ok = count(res%rk4%ok) >= 1
        do i = 1, WP_NRK4
            if (res%rk4(i)%ok) ok = ok .and. res%rk4(i)%error_theta < 1.0e-9_dp
        end do
        call t%check('wp elastic: RK4 points run, stable and within 1e-9 of the reference', ok)
    end subroutine test_elastic_curves

    !> A deck of the cylinder on unequal cables, raised 45 degrees: its analyses and the
    !! variables of its &integration.
    subroutine write_deck(path, analyses, integration)
        character(len=*), intent(in) :: path, analyses, integration
        character, parameter :: NL = new_line('a')
        call write_text(path, '&scene title = ''wp test'', analyses = '''//analyses//''' /'//NL// &
            '&suspension b = 1.0, b_prime = 1.0, l = 2.0, l_prime = 1.8, g = 1.0 /'//NL// &
            '&body mass = 1.0 /'//NL//'&start mode = ''raised'', amplitude = 45.0 /'//NL// &
            '&integration '//integration//' /'//NL)
    end subroutine write_deck

    !> The reference agrees with RK4 + Richardson; LSODA's error falls with rtol and stays
    !! within reach of it; RK4 converges at fourth order; the files have their headers.
    subroutine test_curves(t)
        type(tester_t), intent(inout) :: t
        type(deck_t) :: d
        type(status_t) :: st
        type(wp_result_t) :: res
        real(dp) :: slope
        integer :: i, nrows
        logical :: ok, header
        call write_deck(SCRATCH//'/wp.nml', 'work_precision', &
                        'tau_end = 3.0, dtau_out = 0.05, rtol = 1e-10, atol = 1e-12')
        call read_deck(SCRATCH//'/wp.nml', d, st)
        call t%check('wp: deck reads', st%code == 0)
        if (st%code /= 0) return
        call run_work_precision(d, SCRATCH, res, st, quiet=.true.)
        call t%check('wp: analysis runs', st%code == 0)
        if (st%code /= 0) return
        call t%check('wp: reference LSODA 1e-13 = RK4 + Richardson to 1e-11 in angles', &
                     res%ref_agreement_theta < 1.0e-11_dp)
        call t%check('wp: reference LSODA 1e-13 = RK4 + Richardson to 1e-11 in Q', &
                     res%ref_agreement_q < 1.0e-11_dp)
        call t%check('wp: every LSODA point finished', all(res%lsoda%ok))
        call t%check('wp: every RK4 point finished', all(res%rk4%ok))
        ok = .true.
        do i = 1, WP_NRTOL
            ! within reach of the tolerance: error <= 100 rtol (a floor of 1e-12 at the end)
            ok = ok .and. res%lsoda(i)%error_theta <= max(100.0_dp*res%lsoda(i)%rtol, 1.0e-12_dp)
            ok = ok .and. res%lsoda(i)%error_q <= max(100.0_dp*res%lsoda(i)%rtol, 1.0e-12_dp)
        end do
        call t%check('wp: LSODA errors within 100 rtol', ok)
        ok = .true.
        do i = 1, WP_NRTOL - 2
            ok = ok .and. res%lsoda(i + 2)%error_theta < res%lsoda(i)%error_theta
        end do
        call t%check('wp: LSODA error decreases with rtol (every two decades)', ok)
        call t%check('wp: LSODA 1e-12 error below 1e-6 of the 1e-3 error', &
                     res%lsoda(WP_NRTOL)%error_theta < 1.0e-6_dp*res%lsoda(1)%error_theta)
        call t%check('wp: cost grows with accuracy', &
                     res%lsoda(WP_NRTOL)%rhs_evaluations > 2*res%lsoda(1)%rhs_evaluations)
        ok = .true.
        do i = 1, 4
            slope = log(res%rk4(i)%error_theta/res%rk4(i + 1)%error_theta)/log(2.0_dp)
            ok = ok .and. abs(slope - 4.0_dp) < 0.3_dp
            if (abs(slope - 4.0_dp) >= 0.3_dp) write (*, '(a,i0,a,f8.3)') '   RK4 order ', i, &
                ': ', slope
        end do
        call t%check('wp: RK4 converges at 4th order (4 +- 0.3 over four halvings of h)', ok)
        call t%check('wp: RK4 rhs evaluations = 4 steps', &
                     all(res%rk4%rhs_evaluations == 4*res%rk4%steps))
        call table_file(SCRATCH//'/wp.wp.dat', '# rtol cpu_seconds steps rhs_evaluations '// &
                        'error_theta error_Q max_abs_energy_error', header, nrows)
        call t%check('wp: .wp.dat header and 10 rows', header .and. nrows == WP_NRTOL)
        call table_file(SCRATCH//'/wp.wp_rk4.dat', '# h cpu_seconds steps rhs_evaluations '// &
                        'error_theta error_Q max_abs_energy_error', header, nrows)
        call t%check('wp: .wp_rk4.dat header and 7 rows', header .and. nrows == WP_NRK4)
    end subroutine test_curves

    !> Through the executable: analyses = 'work_precision' writes both files; a simulation
    !! with error_estimate = .true. adds the keys, near the true error; without it, none.
    subroutine test_end_to_end(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        integer :: ex
        logical :: there, f1, f2
        real(dp) :: eth, eq, true_err
        type(deck_t) :: d
        type(status_t) :: st
        type(wp_result_t) :: res
        call write_deck(SCRATCH//'/wp_exe.nml', 'work_precision', &
                        'tau_end = 1.0, dtau_out = 0.1, rtol = 1e-10, atol = 1e-12')
        call execute_command_line(exe//' '//SCRATCH//'/wp_exe.nml --out '//SCRATCH// &
                                  ' > /dev/null 2>&1', exitstat=ex)
        call t%check('wp exe: exit 0', ex == 0)
        inquire (file=SCRATCH//'/wp_exe.wp.dat', exist=f1)
        inquire (file=SCRATCH//'/wp_exe.wp_rk4.dat', exist=f2)
        call t%check('wp exe: both files written', f1 .and. f2)
        ! error estimate at rtol 1e-8 over tau = 10
        call write_deck(SCRATCH//'/ee.nml', 'simulate', 'tau_end = 10.0, '// &
                        'dtau_out = 0.05, rtol = 1e-8, atol = 1e-10, error_estimate = .true.')
        call execute_command_line(exe//' '//SCRATCH//'/ee.nml --out '//SCRATCH// &
                                  ' > /dev/null 2>&1', exitstat=ex)
        call t%check('error estimate: exit 0', ex == 0)
        call read_kv(SCRATCH//'/ee.summary', 'error_estimate_theta', eth, f1)
        call read_kv(SCRATCH//'/ee.summary', 'error_estimate_Q', eq, f2)
        call t%check('error estimate: keys error_estimate_theta, error_estimate_Q', f1 .and. f2)
        call t%check('error estimate: 0 < values <= 100 rtol', eth > 0.0_dp .and. &
                     eq > 0.0_dp .and. eth <= 1.0e-6_dp .and. eq <= 1.0e-6_dp)
        ! honest: within a factor 10 of the error against the work-precision reference
        call read_deck(SCRATCH//'/ee.nml', d, st)
        if (st%code == 0) call run_work_precision(d, SCRATCH, res, st, quiet=.true.)
        if (st%code == 0) then
            true_err = res%lsoda(6)%error_theta      ! rtol 1e-8
            call t%check('error estimate: within a factor 10 of the true angle error', &
                         eth > 0.1_dp*true_err .and. eth < 10.0_dp*true_err)
        else
            call t%check('error estimate: reference runs', .false.)
        end if
        call write_deck(SCRATCH//'/noee.nml', 'simulate', &
                        'tau_end = 1.0, dtau_out = 0.05, rtol = 1e-8, atol = 1e-10')
        call execute_command_line(exe//' '//SCRATCH//'/noee.nml --out '//SCRATCH// &
                                  ' > /dev/null 2>&1', exitstat=ex)
        call read_kv(SCRATCH//'/noee.summary', 'error_estimate_theta', eth, there)
        call t%check('error estimate: no keys unless asked', ex == 0 .and. .not. there)
    end subroutine test_end_to_end

    !> Whether the file has the header line, and how many data rows (finite numbers) follow.
    subroutine table_file(path, head, header, nrows)
        character(len=*), intent(in) :: path, head
        logical, intent(out) :: header
        integer, intent(out) :: nrows
        integer :: u, ios
        character(len=1024) :: line
        real(dp) :: v(7)
        header = .false.
        nrows = 0
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (trim(line) == head) header = .true.
            if (line(1:1) == '#') cycle
            read (line, *, iostat=ios) v
            if (ios == 0) then
                if (all(abs(v) < huge(1.0_dp))) nrows = nrows + 1
            end if
        end do
        close (u)
    end subroutine table_file


end module test_work_precision
