!> Suite platform_tensor: the inertia tensor measured on a platform of three cables
!! (analysis tensor): each hang the platform's own model (module hang_model over
!! platform_measure), the platform's mass and inertia a fixture in the hang's frame.
!! * the model: a centred hang whose vertical is a principal axis has the closed-form period
!!   of the trifilar's pure torsion; an off-axis hang's periodic torsion tends to the
!!   linearised period as the amplitude falls;
!! * exact periods made by the program from a known body (off the platform's axis in some
!!   hangs) give the body's tensor back to 1e-9; the fit without the platform's fixture is
!!   clearly wrong (a principal moment off by more than 5 %);
!! * noisy periods over several seeds: the truth within U (k = 2 at 95 %);
!! * the example deck input/tensor_platform.nml through the executable, and with a Monte
!!   Carlo: its u of each principal moment within 15 % of the first-order u (the samples
!!   run the platform's model, as the fit does);
!! * refusals: one line naming the variable, exit 2, no file.
module test_platform_tensor
    use kinds, only: dp, pi
    use status, only: status_t, STATUS_OK
    use testing, only: tester_t, write_text, file_has, count_lines, scratch_dir, empty_dir, &
                       msg_of, exists, read_kv_text
    use text, only: itoa, sci
    use deck, only: deck_t, read_deck
    use deck_runs, only: accuracy_of
    use rig, only: rig_t, accuracy_t
    use random, only: rng_t, rng_stream, rng_normal
    use measurement, only: measurement_t, hang_t
    use measurement_read, only: read_hangs
    use hang_model, only: tensor_entries, hang_rig, hang_period
    use tensor_fit, only: tensor_problem_t, tensor_fit_t, problem_of, projection, fit_tensor, &
        model_periods, tensor_mc_payload, tensor_mc_task, tensor_mc_task_t, MC_PARTS
    implicit none
    private

    public :: run_platform_tensor_tests

    character(len=*), parameter :: SCR = 'build/test_platform_tensor'
    character(len=*), parameter :: NL = new_line('a')
    real(dp), parameter :: MASS = 4.2_dp, G0 = 9.80665_dp
    real(dp), parameter :: MOMENTS(3) = [0.10_dp, 0.12_dp, 0.15_dp]
    !> The trifilar and the platform (the fixture) of the test decks.
    character(len=*), parameter :: RIG_LINES = &
        '&suspension cables = 3, radius = 0.30, radius_prime = 0.25, l = 1.50, '// &
        'g = 9.80665 /'//NL// &
        '&body mass = 4.2, inertia = 0.10, 0.12, 0.15, cg_depth = -0.06, cg_offset = 0, 0 /'//NL
    character(len=*), parameter :: FIXTURE = "fixture_frame = 'hang', fixture_mass = 1.5, "// &
        'fixture_cg = 0, 0, -0.01, fixture_inertia = 0.024, 0, 0, 0, 0.024, 0, 0, 0, 0.047'
    !> Nine hangs: faces, edges, corners; the body off the axis in five of them.
    character(len=*), parameter :: TABLE = &
        'hang up_x up_y up_z along_x along_y along_z cg_offset cg_offset_y cg_depth period'//NL// &
        '1 1 0 0 0 1 0 0 0 -0.06 1.5'//NL// &
        '2 0 1 0 0 0 1 0.03 0 -0.07 1.5'//NL// &
        '3 0 0 1 1 0 0 0 0.02 -0.05 1.5'//NL// &
        '4 1 1 0 0 0 1 0 0 -0.08 1.5'//NL// &
        '5 1 0 1 0 1 0 -0.02 0.01 -0.08 1.5'//NL// &
        '6 0 1 1 1 0 0 0 0 -0.08 1.5'//NL// &
        '7 1 1 1 1 -1 0 0.015 0 -0.09 1.5'//NL// &
        '8 1 -1 1 1 1 0 0 0 -0.09 1.5'//NL// &
        '9 -1 1 1 1 1 0 0 -0.02 -0.09 1.5'//NL

contains

    subroutine run_platform_tensor_tests(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe     !! path of the bifilar executable
        call scratch_dir(SCR)
        if (t%want('platform_tensor: a centred hang''s period is the trifilar''s torsion')) &
            call test_centred(t)
        if (t%want('platform_tensor: an off-axis hang''s orbit tends to the linear period')) &
            call test_small_limit(t)
        if (t%want('platform_tensor: the tensor back from exact periods; no fixture is wrong')) &
            call test_exact(t)
        if (t%want('platform_tensor: the truth within U over noise seeds')) call test_noise(t)
        if (t%want('platform_tensor: points of the regular rig give the radius form''s')) &
            call test_points_regular(t)
        if (t%want('platform_tensor: an asymmetric point rig gives the truth back')) &
            call test_points_asymmetric(t)
        if (t%want('platform_tensor: the example deck')) call test_example(t, exe)
        if (t%want('platform_tensor: the example point by point, with a Monte Carlo')) &
            call test_points_deck(t, exe)
        if (t%want('platform_tensor: the Monte Carlo runs the platform''s model')) &
            call test_monte_carlo(t, exe)
        if (t%want('platform_tensor: refusals are one line, exit 2 and no file')) &
            call test_refusals(t, exe)
        if (t%want('platform_tensor: identify off the axis names the platform''s model')) &
            call test_identify_model(t, exe)
    end subroutine run_platform_tensor_tests

    !> The true tensor: principal moments MOMENTS about the rows of the rotation of the
    !! quaternion (4, 2, 1, 2)/5 (input/truth/tensor_platform_truth.nml).
    function true_tensor() result(x)
        real(dp) :: x(6)
        real(dp) :: b(3, 3), j(3, 3)
        integer :: k
        b = transpose(reshape([0.60_dp, -0.48_dp, 0.64_dp, 0.80_dp, 0.36_dp, -0.48_dp, &
                               0.0_dp, 0.80_dp, 0.60_dp], [3, 3]))
        j = 0.0_dp
        do k = 1, 3
            j = j + MOMENTS(k)*spread(b(k, :), 2, 3)*spread(b(k, :), 1, 3)
        end do
        x = tensor_entries(j)
    end function true_tensor

    function acc12() result(acc)
        type(accuracy_t) :: acc
        acc%rtol = 1.0e-12_dp
        acc%atol = 1.0e-14_dp
    end function acc12

    !> A hang of the test platform: up, along, the body's mass centre from the centre.
    function platform_hang(up, along, off, off_y, depth) result(h)
        real(dp), intent(in) :: up(3), along(3), off, off_y, depth
        type(hang_t) :: h
        h%cables = 3
        h%b = 0.6_dp
        h%b_prime = 0.5_dp
        h%l = 1.5_dp
        h%l_prime = 1.5_dp
        h%up = up/norm2(up)
        h%along = along/norm2(along)
        h%cg_offset = off
        h%cg_offset_y = off_y
        h%cg_depth = depth
    end function platform_hang

    !> Centred, the vertical a principal axis: the period of the platform's pure torsion,
    !! 2 pi (I h/(m g R R'))^(1/2), h = (l^2 - (R - R')^2)^(1/2) the platform's drop.
    subroutine test_centred(t)
        type(tester_t), intent(inout) :: t
        type(rig_t) :: rg
        type(status_t) :: st
        real(dp) :: x(6), per, want, hgt
        x = [0.10_dp, 0.12_dp, 0.15_dp, 0.0_dp, 0.0_dp, 0.0_dp]
        call hang_rig(MASS, G0, platform_hang([0.0_dp, 0.0_dp, 1.0_dp], [1.0_dp, 0.0_dp, &
                      0.0_dp], 0.0_dp, 0.0_dp, -0.05_dp), x, rg, st)
        if (st%code == STATUS_OK) call hang_period(rg, acc12(), 0.0_dp, per, st)
        call t%check('centred: the period: '//msg_of(st), st%code == STATUS_OK)
        hgt = sqrt(1.5_dp**2 - (0.30_dp - 0.25_dp)**2)
        want = 2.0_dp*pi*sqrt(0.15_dp*hgt/(MASS*G0*0.30_dp*0.25_dp))
        call t%check_close('centred: the trifilar''s closed form', per, want, rtol=1.0e-10_dp)
    end subroutine test_centred

    !> Off the axis, the vertical no principal axis: the periodic torsion's period at 0.2
    !! degrees within 1e-5 of the linearised one (the difference is O(A^2)).
    subroutine test_small_limit(t)
        type(tester_t), intent(inout) :: t
        type(rig_t) :: rg
        type(status_t) :: st
        real(dp) :: p0, pa
        call hang_rig(MASS, G0, platform_hang([1.0_dp, 0.0_dp, 1.0_dp], [0.0_dp, 1.0_dp, &
                      0.0_dp], -0.02_dp, 0.01_dp, -0.08_dp), true_tensor(), rg, st)
        if (st%code == STATUS_OK) call hang_period(rg, acc12(), 0.0_dp, p0, st)
        if (st%code == STATUS_OK) call hang_period(rg, acc12(), 0.2_dp, pa, st)
        call t%check('small limit: the periods: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        call t%check_close('small limit: orbit at 0.2 deg near the linear period', pa, p0, &
                           rtol=1.0e-5_dp)
    end subroutine test_small_limit

    !> The problem of the test deck (extra: more &tensor keys) with the periods the
    !! program's model gives the true tensor with the platform as fixture, plus noise(i).
    !! rig: the deck's &suspension line in place of the trifilar's; periods: the problem
    !! whose model gives the periods (default: this one).
    subroutine make_problem(label, extra, prob, st, noise, rig, periods)
        character(len=*), intent(in) :: label, extra
        type(tensor_problem_t), intent(out) :: prob
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: noise(:)
        character(len=*), intent(in), optional :: rig
        type(tensor_problem_t), intent(in), optional :: periods
        type(deck_t) :: d
        type(measurement_t) :: set
        real(dp), allocatable :: tc(:)
        character(len=:), allocatable :: lines
        integer :: i
        lines = RIG_LINES
        if (present(rig)) lines = rig//NL//RIG_LINES(index(RIG_LINES, NL) + 1:)
        call write_text(SCR//'/'//label//'.txt', TABLE)
        call write_text(SCR//'/'//label//'.nml', "&scene analyses = 'tensor' /"//NL// &
            lines//"&integration rtol = 1e-12, atol = 1e-14 /"//NL// &
            "&tensor hangs = '"//label//".txt', "//FIXTURE//extra//' /'//NL)
        call read_deck(SCR//'/'//label//'.nml', d, st)
        if (st%code /= STATUS_OK) return
        call read_hangs(d%tensor, d%suspension, d%body, set, st)
        if (st%code /= STATUS_OK) return
        call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set, prob)
        allocate (tc(size(prob%case_hang)))
        if (present(periods)) then
            call model_periods(periods, true_tensor(), tc, st)
        else
            call model_periods(prob, true_tensor(), tc, st)
        end if
        if (st%code /= STATUS_OK) return
        do i = 1, size(prob%rows)
            prob%rows(i)%period = tc(prob%row_case(i))
            if (present(noise)) prob%rows(i)%period = prob%rows(i)%period + noise(i)
        end do
    end subroutine make_problem

    !> Exact periods: the six entries and the principal moments back to 1e-9; the fit
    !! without the platform's fixture misses a principal moment by more than 5 %.
    subroutine test_exact(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob, bare
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        real(dp) :: xp(6), x(6)
        integer :: k
        x = true_tensor()
        call make_problem('exact', '', prob, st)
        call t%check('exact: the problem: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        call t%check('exact: five hangs off the axis', count(abs(prob%hangs%cg_offset) + &
                     abs(prob%hangs%cg_offset_y) > 0.0_dp) == 5)
        call projection(prob, xp, st)
        if (st%code == STATUS_OK) call fit_tensor(prob, xp, fit, st)
        call t%check('exact: the fit: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        do k = 1, 6
            call t%check_close('exact: entry '//itoa(k), fit%x(k), x(k), rtol=0.0_dp, &
                               atol=1.0e-9_dp*MOMENTS(3))
        end do
        do k = 1, 3
            call t%check_close('exact: principal moment '//itoa(k), fit%moments(k), &
                               MOMENTS(k), rtol=1.0e-9_dp)
        end do
        ! the same periods fitted as if the body hung alone (no platform): clearly wrong
        bare = prob
        bare%fix%mass = 0.0_dp
        bare%fix%inertia = 0.0_dp
        bare%loaded = .false.
        call projection(bare, xp, st)
        if (st%code == STATUS_OK) call fit_tensor(bare, xp, fit, st)
        if (st%code == STATUS_OK) then
            write (*, '(a,3(1x,es12.5))') '   principal moments without the platform:', &
                fit%moments
            call t%check('no fixture: a principal moment off by more than 5 % (50 times '// &
                         'its u of exact periods)', maxval(abs(fit%moments/MOMENTS - 1.0_dp)) &
                         > 0.05_dp)
        else
            call t%check('no fixture: refused ('//msg_of(st)//')', .true.)
        end if
    end subroutine test_exact

    !> The trifilar given point by point (its three points at the radii, every length l):
    !! the same periods give the radius form's entries to 1e-10 of I_max, and their u (a
    !! stated u of the timings, 2e-4 s) to 1e-6.
    subroutine test_points_regular(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: pr, pp
        type(tensor_fit_t) :: fr, fp
        type(status_t) :: st
        real(dp) :: xp(6)
        integer :: k
        call make_problem('radius', ', u_period = 2e-4', pr, st)
        if (st%code == STATUS_OK) call make_problem('regular_points', ', u_period = 2e-4', &
            pp, st, rig=regular_points(), periods=pr)
        call t%check('regular points: the problems: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        call t%check('regular points: the problem holds the points', pp%pts%given .and. &
                     .not. pr%pts%given)
        call projection(pr, xp, st)
        if (st%code == STATUS_OK) call fit_tensor(pr, xp, fr, st)
        if (st%code == STATUS_OK) call projection(pp, xp, st)
        if (st%code == STATUS_OK) call fit_tensor(pp, xp, fp, st)
        call t%check('regular points: the fits: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        do k = 1, 6
            call t%check_close('regular points: entry '//itoa(k), fp%x(k), fr%x(k), &
                               rtol=0.0_dp, atol=1.0e-10_dp*MOMENTS(3))
            call t%check_close('regular points: u of entry '//itoa(k), fp%u_x(k), fr%u_x(k), &
                               rtol=1.0e-6_dp)
        end do
    contains
        !> &suspension of the test trifilar point by point: cable i at angle 2 pi (i-1)/3.
        function regular_points() result(line)
            character(len=:), allocatable :: line
            character(len=:), allocatable :: sp, bp
            real(dp) :: a
            integer :: i
            sp = ''
            bp = ''
            do i = 1, 3
                a = 2.0_dp*pi*(i - 1)/3.0_dp
                sp = sp//sci(0.30_dp*cos(a), 17)//', '//sci(0.30_dp*sin(a), 17)//', 0, '
                bp = bp//sci(0.25_dp*cos(a), 17)//', '//sci(0.25_dp*sin(a), 17)//', 0, '
            end do
            line = '&suspension cables = 3, support_points = '//sp//'body_points = '//bp// &
                'lengths = 1.5, 1.5, 1.5, g = 9.80665 /'
        end function regular_points
    end subroutine test_points_regular

    !> A platform of three cables at no regular polygon (unequal lengths, the points off
    !! their circles and heights): exact periods of its own model give the truth back to
    !! 1e-9 of I_max; its periods are not the regular rig's of the same scales (the points
    !! reach the model).
    subroutine test_points_asymmetric(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob, reg
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        real(dp) :: xp(6), x(6)
        real(dp), allocatable :: tp(:), tr(:)
        character(len=*), parameter :: ASYM = '&suspension cables = 3, support_points = '// &
            '0.31, 0.01, 0,  -0.14, 0.27, 0.005,  -0.16, -0.25, -0.004, body_points = '// &
            '0.26, 0, 0,  -0.12, 0.22, 0.003,  -0.13, -0.21, 0, lengths = 1.50, 1.49, 1.52, '// &
            'g = 9.80665 /'
        integer :: k
        x = true_tensor()
        call make_problem('asym_points', '', prob, st, rig=ASYM)
        call t%check('asymmetric points: the problem: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        call projection(prob, xp, st)
        if (st%code == STATUS_OK) call fit_tensor(prob, xp, fit, st)
        call t%check('asymmetric points: the fit: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        do k = 1, 6
            call t%check_close('asymmetric points: entry '//itoa(k), fit%x(k), x(k), &
                               rtol=0.0_dp, atol=1.0e-9_dp*MOMENTS(3))
        end do
        call payload_round_trip(t, prob, fit)
        ! the same scales as a regular polygon: other periods
        reg = prob
        reg%pts%given = .false.
        allocate (tp(size(prob%case_hang)), tr(size(prob%case_hang)))
        call model_periods(prob, x, tp, st)
        if (st%code == STATUS_OK) call model_periods(reg, x, tr, st)
        call t%check('asymmetric points: the regular polygon of its scales: '//msg_of(st), &
                     st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        write (*, '(a,es10.3)') '   asymmetric points: largest relative period change '// &
            'from the regular polygon of their scales:', maxval(abs(tp/tr - 1.0_dp))
        call t%check('asymmetric points: the points reach the model (periods differ from '// &
                     'the regular polygon''s by more than 1e-4)', &
                     maxval(abs(tp/tr - 1.0_dp)) > 1.0e-4_dp)
    end subroutine test_points_asymmetric

    !> The Monte Carlo's payload of a fit of the asymmetric point rig read back (as another
    !! rank reads it, with the deck): the hangs, the rows, the estimate, its chord and the
    !! points; the payload one entry short is refused.
    subroutine payload_round_trip(t, prob, fit)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t), intent(in) :: prob
        type(tensor_fit_t), intent(in) :: fit
        type(deck_t) :: d
        type(tensor_mc_task_t) :: task
        type(status_t) :: st
        real(dp), allocatable :: p(:), parts(:, :)
        integer :: h
        logical :: same
        allocate (parts(MC_PARTS, size(prob%case_hang)))
        parts = reshape([(0.001_dp*h, h=1, size(parts))], shape(parts))
        p = tensor_mc_payload(prob, fit, 7, parts)
        call read_deck(SCR//'/asym_points.nml', d, st)
        if (st%code == STATUS_OK) call tensor_mc_task(d%tensor, d%suspension, d%body, &
            accuracy_of(d), p, task, st)
        call t%check('payload: read back: '//msg_of(st), st%code == STATUS_OK)
        if (st%code /= STATUS_OK) return
        same = task%seed == 7 .and. size(task%prob%hangs) == size(prob%hangs) .and. &
            size(task%prob%rows) == size(prob%rows)
        call t%check('payload: the seed and the counts', same)
        if (.not. same) return
        do h = 1, size(prob%hangs)
            same = same .and. all(task%prob%hangs(h)%up == prob%hangs(h)%up) .and. &
                all(task%prob%hangs(h)%along == prob%hangs(h)%along) .and. &
                task%prob%hangs(h)%cg_offset_y == prob%hangs(h)%cg_offset_y .and. &
                task%prob%hangs(h)%cables == 3
        end do
        call t%check('payload: every hang', same)
        call t%check('payload: the rows'' periods and u_def', &
                     all(task%prob%rows%period == prob%rows%period) .and. &
                     all(task%prob%u_def == prob%u_def))
        call t%check('payload: the estimate, its u and its chord', all(task%x == fit%x) .and. &
                     all(task%u_x == fit%u_x) .and. all(task%chord == fit%chord(1:6, :)))
        call t%check('payload: the amplitude parts', all(task%parts == parts))
        call t%check('payload: the points reach the task', task%prob%pts%given .and. &
                     all(task%prob%pts%support == prob%pts%support))
        call tensor_mc_task(d%tensor, d%suspension, d%body, accuracy_of(d), &
                            p(1:size(p) - 1), task, st)
        call t%check('payload: one entry short refused', st%code /= STATUS_OK)
    end subroutine payload_round_trip

    !> Timing noise of u_period = 2e-4 s per period (10 seeds): each principal moment
    !! within U = k95 u of the truth in at least 9 of 10 seeds.
    subroutine test_noise(t)
        type(tester_t), intent(inout) :: t
        type(tensor_problem_t) :: prob
        type(tensor_fit_t) :: fit
        type(status_t) :: st
        type(rng_t) :: g
        real(dp) :: xp(6), noise(9)
        real(dp), parameter :: U_T = 2.0e-4_dp
        integer :: seed, k, covered(3)
        covered = 0
        do seed = 1, 10
            g = rng_stream(seed, 0)
            do k = 1, 9
                noise(k) = U_T*rng_normal(g)
            end do
            call make_problem('noise', ', u_period = 2e-4', prob, st, noise)
            if (st%code == STATUS_OK) call projection(prob, xp, st)
            if (st%code == STATUS_OK) call fit_tensor(prob, xp, fit, st)
            if (st%code /= STATUS_OK) then
                call t%check('noise seed '//itoa(seed)//': '//msg_of(st), .false.)
                cycle
            end if
            do k = 1, 3
                if (abs(fit%moments(k) - MOMENTS(k)) <= fit%k95(k)*fit%u_moments(k)) &
                    covered(k) = covered(k) + 1
            end do
        end do
        write (*, '(a,3(i0,1x),a)') '   95 % intervals covering the truth: ', covered, &
            'of 10 (principal moments 1, 2, 3)'
        do k = 1, 3
            call t%check('noise: moment '//itoa(k)//' within U in '//itoa(covered(k))// &
                         ' of 10 (>= 9)', covered(k) >= 9)
        end do
        call t%check('noise: u is not vacuous (u of moment 3 < 1 %)', &
                     fit%u_moments(3) < 0.01_dp*MOMENTS(3))
    end subroutine test_noise

    !> input/tensor_platform.nml runs: exit 0, its files, the principal moments of the
    !! truth deck to the 1e-9 s of its periods' digits.
    subroutine test_example(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: DIR = SCR//'/example'
        character(len=512) :: v
        real(dp) :: m(3)
        integer :: ex, ios
        call execute_command_line('rm -rf '//DIR//' && mkdir -p '//DIR//' && '//exe// &
            ' input/tensor_platform.nml --out '//DIR//' > '//DIR//'.stdout 2> '//DIR// &
            '.stderr', exitstat=ex)
        call t%check('example: exit 0', ex == 0)
        call t%check('example: its .tensor', exists(DIR//'/tensor_platform.tensor'))
        call t%check('example: its .tensor.dat', exists(DIR//'/tensor_platform.tensor.dat'))
        call t%check('example: its certificate', &
                     exists(DIR//'/tensor_platform.certificate.html'))
        call t%check('example: nothing on stderr', count_lines(DIR//'.stderr') == 0)
        call certificate_words(t, DIR//'/tensor_platform.certificate.html')
        call read_kv_text(DIR//'/tensor_platform.tensor', 'I_principal', v)
        read (v, *, iostat=ios) m
        call t%check('example: I_principal read', ios == 0)
        if (ios /= 0) return
        call t%check('example: the truth''s principal moments to 1e-7 ('//sci(m(1))//', '// &
                     sci(m(2))//', '//sci(m(3))//')', &
                     maxval(abs(m/MOMENTS - 1.0_dp)) < 1.0e-7_dp)
    end subroutine test_example

    !> A platform's certificate says what the platform is (cables, R, R', l) and where the
    !! mass centre is measured from (the platform's centre, the attachment plane, x and y),
    !! not a bifilar's b, b' and strings' midpoint.
    subroutine certificate_words(t, file)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: file
        character(len=*), parameter :: HAS(6) = [character(len=30) :: 'cables', &
            'R (radius, at the support)', 'l (every cable)', 'cg_offset_y (y)', &
            'attachment plane', 'along (the platform']
        character(len=*), parameter :: NOT(3) = [character(len=30) :: 'b (at the support)', &
            'midpoint of the strings', 'along (C to D)']
        integer :: k
        do k = 1, size(HAS)
            call t%check('certificate: says '''//trim(HAS(k))//'''', file_has(file, &
                         trim(HAS(k))))
        end do
        do k = 1, size(NOT)
            call t%check('certificate: no bifilar''s '''//trim(NOT(k))//'''', &
                         .not. file_has(file, trim(NOT(k))))
        end do
    end subroutine certificate_words

    !> input/tensor_platform.nml with its trifilar given point by point and monte_carlo =
    !! 200: exit 0, the truth's principal moments to 1e-7, the Monte Carlo's u within 15 %
    !! of the first-order u (its samples run the points' model), the certificate names the
    !! points.
    subroutine test_points_deck(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: DIR = SCR//'/ptsdeck'
        character(len=*), parameter :: SUS = '\&suspension cables = 3, support_points = '// &
            '0.3, 0, 0, -0.15, 0.25980762113533160, 0, -0.15, -0.25980762113533160, 0, '// &
            'body_points = 0.25, 0, 0, -0.125, 0.21650635094610965, 0, -0.125, '// &
            '-0.21650635094610965, 0, lengths = 1.5, 1.5, 1.5, g = 9.80665 /'
        character(len=512) :: v
        real(dp) :: m(3), u1(3), umc(3)
        integer :: ex, ios
        call execute_command_line('rm -rf '//DIR//' && mkdir -p '//DIR//' && sed -e '// &
            '"s/monte_carlo = 0 /monte_carlo = 200 /" -e "s|^&suspension.*|'//SUS//'|" '// &
            'input/tensor_platform.nml > '//DIR//'/pts.nml && cp input/tensor_platform_hangs.csv '// &
            DIR//'/ && '//exe//' '//DIR//'/pts.nml --out '//DIR//'/out > '//DIR// &
            '.stdout 2> '//DIR//'.stderr', exitstat=ex)
        call t%check('points deck: exit 0', ex == 0)
        call t%check('points deck: the deck is point by point', &
                     file_has(DIR//'/pts.nml', 'support_points'))
        call read_kv_text(DIR//'/out/pts.tensor', 'I_principal', v)
        read (v, *, iostat=ios) m
        if (ios == 0) then
            call read_kv_text(DIR//'/out/pts.tensor', 'u_I_principal', v)
            read (v, *, iostat=ios) u1
        end if
        if (ios == 0) then
            call read_kv_text(DIR//'/out/pts.tensor', 'u_I_principal_monte_carlo', v)
            read (v, *, iostat=ios) umc
        end if
        call t%check('points deck: its results read', ios == 0)
        if (ios /= 0) return
        call t%check('points deck: the truth''s principal moments to 1e-7', &
                     maxval(abs(m/MOMENTS - 1.0_dp)) < 1.0e-7_dp)
        write (*, '(a,3f8.4)') '  points deck: Monte Carlo u over first-order u:', umc/u1
        call t%check('points deck: the Monte Carlo''s u within 15 % of the first-order u', &
                     all(abs(umc/u1 - 1.0_dp) < 0.15_dp))
        call t%check('points deck: the certificate names the points', &
                     file_has(DIR//'/out/pts.certificate.html', 'given point by point'))
    end subroutine test_points_deck

    !> The example deck with monte_carlo = 300: the samples' u of each principal moment within
    !! 15 % of the first-order u (a sample that ran the bifilar's model instead of the
    !! platform's gave up to 1.8 times it).
    subroutine test_monte_carlo(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: DIR = SCR//'/mc'
        character(len=512) :: v
        real(dp) :: u1(3), umc(3)
        integer :: ex, ios
        call execute_command_line('rm -rf '//DIR//' && mkdir -p '//DIR//' && sed '// &
            '"s/monte_carlo = 0 /monte_carlo = 300 /" input/tensor_platform.nml > '//DIR// &
            '/mc.nml && cp input/tensor_platform_hangs.csv '//DIR//'/ && '//exe//' '//DIR// &
            '/mc.nml --out '//DIR//'/out > '//DIR//'.stdout 2> '//DIR//'.stderr', exitstat=ex)
        call t%check('Monte Carlo: exit 0', ex == 0)
        call read_kv_text(DIR//'/out/mc.tensor', 'u_I_principal', v)
        read (v, *, iostat=ios) u1
        if (ios == 0) then
            call read_kv_text(DIR//'/out/mc.tensor', 'u_I_principal_monte_carlo', v)
            read (v, *, iostat=ios) umc
        end if
        call t%check('Monte Carlo: u_I_principal and its Monte Carlo read', ios == 0)
        if (ios /= 0) return
        write (*, '(a,3f8.4)') '  platform tensor: Monte Carlo u over first-order u:', umc/u1
        call t%check('Monte Carlo: its u of each principal moment within 15 % of the '// &
                     'first-order u', all(abs(umc/u1 - 1.0_dp) < 0.15_dp))
    end subroutine test_monte_carlo

    !> Bad platform decks: exit 2, one stderr line naming the deck and the variable, no file.
    subroutine test_refusals(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: HEAD = 'hang up_x up_y up_z along_x along_y along_z '// &
            'period'//NL
        character(len=*), parameter :: ROWS = '1 1 0 0 0 1 0 1.5'//NL//'2 0 1 0 0 0 1 1.5'// &
            NL//'3 0 0 1 1 0 0 1.5'//NL//'4 1 1 0 0 0 1 1.5'//NL//'5 1 0 1 0 1 0 1.5'//NL// &
            '6 0 1 1 1 0 0 1.5'//NL
        character(len=*), parameter :: SUS4 = '&suspension cables = 4, radius = 0.30, '// &
            'radius_prime = 0.25, l = 1.50, g = 9.80665 /'
        character(len=*), parameter :: PTS = '&suspension cables = 3, support_points = '// &
            '0.3, 0, 0, -0.15, 0.26, 0, -0.15, -0.26, 0, body_points = 0.25, 0, 0, '// &
            '-0.125, 0.2165, 0, -0.125, -0.2165, 0, g = 9.80665'
        call one('cables4', HEAD//ROWS, '&suspension cables', FIXTURE, SUS4)
        call one('frame', HEAD//ROWS, '&tensor fixture_frame', &
                 "fixture_frame = 'body', fixture_mass = 1.5")
        call one('estimate', HEAD//ROWS, '&tensor estimate', FIXTURE//", estimate = 'tensor cg'")
        call one('points', 'hang c_x c_y c_z d_x d_y d_z period'//NL// &
                 '1 0 0 0 1 0 0 1.5'//NL, 'attachment points c_x', FIXTURE//', cg = 0, 0, 0')
        call one('bprime', 'hang up_x up_y up_z along_x along_y along_z b_prime period'//NL// &
                 '1 1 0 0 0 1 0 0.5 1.5'//NL, 'column ''b_prime''', FIXTURE)
        ! a platform point by point: lengths missing, the platform's points collinear,
        ! both forms at once
        call one('nolengths', HEAD//ROWS, '&suspension lengths', FIXTURE, PTS//' /')
        call one('collinear', HEAD//ROWS, '&suspension body_points', FIXTURE, &
                 '&suspension cables = 3, support_points = 0.3, 0, 0, -0.15, 0.26, 0, '// &
                 '-0.15, -0.26, 0, body_points = 0.25, 0, 0, 0, 0, 0, -0.25, 0, 0, '// &
                 'lengths = 1.5, 1.5, 1.5, g = 9.80665 /')
        call one('bothforms', HEAD//ROWS, '&suspension radius', FIXTURE, &
                 PTS//', radius = 0.3, lengths = 1.5, 1.5, 1.5 /')
        call one('elastic', HEAD//ROWS, '&scene model', FIXTURE, &
                 "&scene analyses = 'tensor', model = 'elastic' /")
    contains
        !> The deck of `table` with &tensor keys `keys` (and the deck line `line` in
        !! place of the rig's) refused: exit 2, one stderr line naming the deck and
        !! holding `word`, no file.
        subroutine one(label, tab, word, keys, line)
            character(len=*), intent(in) :: label, tab, word, keys
            character(len=*), intent(in), optional :: line
            character(len=:), allocatable :: dir, head
            integer :: ex
            logical :: l1, l2, l3
            dir = SCR//'/ref_'//label
            head = "&scene analyses = 'tensor' /"//NL//RIG_LINES
            if (present(line)) then
                if (line(1:6) == '&scene') then
                    head = line//NL//RIG_LINES
                else
                    head = "&scene analyses = 'tensor' /"//NL//line//NL// &
                        '&body mass = 4.2, inertia = 0.10, 0.12, 0.15, cg_depth = -0.06 /'//NL
                end if
            end if
            call write_text(dir//'.txt', tab)
            call write_text(dir//'.nml', head//"&tensor hangs = 'ref_"//label//".txt', "// &
                            keys//' /'//NL)
            call execute_command_line('rm -rf '//dir//' && mkdir -p '//dir//' && '//exe// &
                ' '//dir//'.nml --out '//dir//' > '//dir//'.stdout 2> '//dir//'.stderr', &
                exitstat=ex)
            call t%check('refusal '//label//': exit 2', ex == 2)
            l1 = count_lines(dir//'.stderr') == 1
            l2 = file_has(dir//'.stderr', dir//'.nml')
            l3 = file_has(dir//'.stderr', word)
            call t%check('refusal '//label//': one stderr line naming the deck and '''// &
                         word//'''', l1 .and. l2 .and. l3)
            call t%check('refusal '//label//': no file', empty_dir(dir))
        end subroutine one
    end subroutine test_refusals

    !> identify on a trifilar with the body off the axis: its summary line names the
    !! period model 'platform orbit' (the platform's periodic torsion).
    subroutine test_identify_model(t, exe)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: exe
        character(len=*), parameter :: DIR = SCR//'/idoff'
        integer :: ex
        call write_text(DIR//'.nml', "&scene analyses = 'identify' /"//NL// &
            '&suspension cables = 3, radius = 0.135, radius_prime = 0.135, l = 1.0, '// &
            'g = 9.81 /'//NL//'&body mass = 2.0, inertia = 0.02, 0.014, 0.014, '// &
            'cg_depth = -0.03, cg_offset = 0.02, 0.0 /'//NL// &
            '&measurement periods = 14.9, 14.95, cycles = 10, amplitudes = 5, 5, '// &
            'u_period = 0.02 /'//NL)
        call execute_command_line('rm -rf '//DIR//' && mkdir -p '//DIR//' && '//exe//' '// &
            DIR//'.nml --out '//DIR//' > '//DIR//'.stdout 2> '//DIR//'.stderr', exitstat=ex)
        call t%check('identify off the axis: exit 0', ex == 0)
        call t%check('identify off the axis: period model platform orbit', &
                     file_has(DIR//'.stdout', 'period model platform orbit'))
    end subroutine test_identify_model

end module test_platform_tensor
