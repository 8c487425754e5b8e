!> The paper's claims for Figs. 4-8 and 10-12, measured on our output files.
!!
!! Reads the .dat files of the paper's scenes (cylinder_l180, cylinder_l195, triangle_plate,
!! cylinder_torsion) and sets each claim of Kane & Tseng beside our value.  Used by
!! `bifilar --report` (output/report.md) and by the tests, so both judge the same numbers.
module paper_claims
    use kinds, only: dp, pi
    use status, only: status_t, set_error, ERR_IO
    use output_io, only: atomic_open, atomic_commit, read_kv
    use text, only: itoa, sci
    use geometry, only: pendulum_t
    use start_pose, only: raised_angles
    use bifilar_model, only: chart_state
    use floquet, only: jacobian_z
    use lapack_wrap, only: la_eig
    implicit none
    private

    integer, parameter :: NCOL = 17
    integer, parameter, public :: COL_THETA1 = 2, COL_THETA4 = 5, COL_Q = 12
    integer, parameter, public :: NCLAIMS = 9     !! claims measured by evaluate_claims

    !> Columns of one output file.
    type, public :: series_t
        real(dp), allocatable :: v(:, :)        !! (rows, 17) in the order of the header
    end type series_t

    !> A figure of `make run` (plots/NAME.png, drawn by plots/NAME.gp) and where the report
    !! shows it: beside claim k (section = k > 0), or in the section on stability (-1),
    !! elastic cables (-2) or accuracy against run time (-3).
    type, public :: figure_t
        character(len=:), allocatable :: name       !! plots/NAME.png
        character(len=:), allocatable :: caption
        integer :: section = 0
    end type figure_t

    !> One claim of the paper beside our value.
    type, public :: claim_t
        character(len=:), allocatable :: what   !! the claim, in the paper's words
        character(len=:), allocatable :: paper  !! the paper's value or statement
        real(dp) :: ours = 0.0_dp               !! our measured value
        character(len=:), allocatable :: measure  !! what `ours` is
        logical :: holds = .false.              !! our value supports the claim
    end type claim_t

    public :: read_series, tilt_frequency, peak_regularity, evaluate_claims, write_report
    public :: report_figures, plots_link
    public :: dominant_frequency, half_period_spread, mean_half_period, rest_frequencies

contains

    !> Read the numeric rows of a bifilar .dat file (lines starting with # are skipped).
    subroutine read_series(path, s, stat)
        character(len=*), intent(in) :: path    !! file to read
        type(series_t), intent(out) :: s
        type(status_t), intent(out) :: stat     !! ERR_IO when missing or malformed
        integer :: u, ios, n, k
        character(len=1024) :: line
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) then
            call set_error(stat, ERR_IO, 'cannot open '//path//' (run its deck first)')
            return
        end if
        n = 0
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) /= '#' .and. len_trim(line) > 0) n = n + 1
        end do
        allocate (s%v(n, NCOL))
        rewind (u)
        k = 0
        do while (k < n)
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
            k = k + 1
            read (line, *, iostat=ios) s%v(k, :)
            if (ios /= 0) then
                call set_error(stat, ERR_IO, 'malformed row in '//path)
                exit
            end if
        end do
        close (u)
    end subroutine read_series

    !> Mean frequency (cycles per unit tau) of a column about its mean, from up-crossings.
    pure real(dp) function tilt_frequency(s, col) result(f)
        type(series_t), intent(in) :: s
        integer, intent(in) :: col              !! column (COL_THETA1 for tilting)
        real(dp) :: m, t1, t2
        integer :: k, ncross
        m = sum(s%v(:, col))/size(s%v, 1)
        ncross = 0
        t1 = 0.0_dp
        t2 = 0.0_dp
        do k = 2, size(s%v, 1)
            if (s%v(k - 1, col) < m .and. s%v(k, col) >= m) then
                ncross = ncross + 1
                if (ncross == 1) t1 = s%v(k, 1)
                t2 = s%v(k, 1)
            end if
        end do
        f = 0.0_dp
        if (ncross >= 2) f = (ncross - 1)/(t2 - t1)
    end function tilt_frequency

    !> Smallest over largest local maximum of |column|: 1 for a perfectly regular oscillation.
    pure real(dp) function peak_regularity(s, col) result(ratio)
        type(series_t), intent(in) :: s
        integer, intent(in) :: col
        real(dp) :: pmin, pmax, a0, a1, a2
        integer :: k
        pmin = huge(1.0_dp)
        pmax = 0.0_dp
        do k = 2, size(s%v, 1) - 1
            a0 = abs(s%v(k - 1, col)); a1 = abs(s%v(k, col)); a2 = abs(s%v(k + 1, col))
            if (a1 > a0 .and. a1 >= a2) then
                pmin = min(pmin, a1)
                pmax = max(pmax, a1)
            end if
        end do
        ratio = 0.0_dp
        if (pmax > 0.0_dp) ratio = pmin/pmax
    end function peak_regularity


    !> Frequency (cycles per unit tau) of the highest peak of the Hann-windowed discrete
    !! Fourier transform of a column, searched on [fmin, fmax] with step 1e-3 and refined
    !! by a parabola through the peak and its neighbours.
    pure real(dp) function dominant_frequency(s, col, fmin, fmax) result(fpk)
        type(series_t), intent(in) :: s
        integer, intent(in) :: col
        real(dp), intent(in) :: fmin, fmax     !! search band (cycles per unit tau)
        real(dp), parameter :: df = 1.0e-3_dp
        real(dp) :: x(size(s%v, 1))
        real(dp), allocatable :: p(:)
        real(dp) :: c, sn, arg, a, b, g
        integer :: n, k, j, nf, kmax
        n = size(s%v, 1)
        x = s%v(:, col) - sum(s%v(:, col))/n
        do j = 1, n
            x(j) = x(j)*0.5_dp*(1.0_dp - cos(2.0_dp*pi*(j - 1)/(n - 1)))
        end do
        nf = int((fmax - fmin)/df) + 1
        allocate (p(nf))
        do k = 1, nf
            c = 0.0_dp
            sn = 0.0_dp
            do j = 1, n
                arg = 2.0_dp*pi*(fmin + (k - 1)*df)*s%v(j, 1)
                c = c + x(j)*cos(arg)
                sn = sn + x(j)*sin(arg)
            end do
            p(k) = c*c + sn*sn
        end do
        kmax = maxloc(p, 1)
        fpk = fmin + (kmax - 1)*df
        if (kmax > 1 .and. kmax < nf) then
            a = p(kmax - 1); b = p(kmax); g = p(kmax + 1)
            if (a - 2*b + g < 0.0_dp) fpk = fpk + 0.5_dp*df*(a - g)/(a - 2*b + g)
        end if
    end function dominant_frequency

    !> Times between successive zero crossings of a column (linear interpolation):
    !! gaps(1:ng).
    pure subroutine zero_gaps(s, col, gaps, ng)
        type(series_t), intent(in) :: s
        integer, intent(in) :: col
        real(dp), intent(out) :: gaps(:)        !! size >= rows of s
        integer, intent(out) :: ng
        real(dp) :: tz, tprev, y0, y1
        integer :: k, nz
        nz = 0
        ng = 0
        gaps = 0.0_dp
        tprev = 0.0_dp
        do k = 2, size(s%v, 1)
            y0 = s%v(k - 1, col); y1 = s%v(k, col)
            if ((y0 < 0.0_dp .and. y1 >= 0.0_dp) .or. (y0 > 0.0_dp .and. y1 <= 0.0_dp)) then
                nz = nz + 1
                tz = s%v(k - 1, 1) + (s%v(k, 1) - s%v(k - 1, 1))*y0/(y0 - y1)
                if (nz >= 2) then
                    ng = ng + 1
                    gaps(ng) = tz - tprev
                end if
                tprev = tz
            end if
        end do
    end subroutine zero_gaps

    !> (largest - smallest)/mean of the half-periods of a column: 0 for a regular oscillation.
    pure real(dp) function half_period_spread(s, col) result(spread)
        type(series_t), intent(in) :: s
        integer, intent(in) :: col
        real(dp) :: gaps(size(s%v, 1))
        integer :: ng
        call zero_gaps(s, col, gaps, ng)
        spread = huge(1.0_dp)
        if (ng >= 2) spread = (maxval(gaps(1:ng)) - minval(gaps(1:ng)))/(sum(gaps(1:ng))/ng)
    end function half_period_spread

    !> Mean half-period of a column (units of tau).
    pure real(dp) function mean_half_period(s, col) result(hp)
        type(series_t), intent(in) :: s
        integer, intent(in) :: col
        real(dp) :: gaps(size(s%v, 1))
        integer :: ng
        call zero_gaps(s, col, gaps, ng)
        hp = 0.0_dp
        if (ng >= 1) hp = sum(gaps(1:ng))/ng
    end function mean_half_period

    !> Natural frequencies (cycles per unit tau) of the pendulum linearised about rest with
    !! equal cables (the symmetric hang of p), from the eigenvalues of Z (LAPACK DGEEV).
    subroutine rest_frequencies(p, freq, nfreq, stat)
        type(pendulum_t), intent(in) :: p       !! scaled parameters (cables made equal here)
        real(dp), intent(out) :: freq(5)        !! the distinct frequencies, ascending
        integer, intent(out) :: nfreq
        type(status_t), intent(out) :: stat
        type(pendulum_t) :: ps
        real(dp) :: th(5), z(10, 10), w
        complex(dp) :: lam(10)
        integer :: k
        nfreq = 0
        freq = 0.0_dp
        ps = p
        ps%big_lp = ps%big_l
        call raised_angles(ps, 0.0_dp, th, stat)
        if (stat%code /= 0) return
        call jacobian_z(ps, chart_state(th, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]), z, stat)
        if (stat%code /= 0) return
        call la_eig(z, lam, stat)
        if (stat%code /= 0) return
        do k = 1, 10
            w = aimag(lam(k))
            if (w > 1.0e-6_dp) then
                nfreq = nfreq + 1
                freq(nfreq) = w/(2.0_dp*pi)
            end if
        end do
    end subroutine rest_frequencies

    pure real(dp) function maxabs(s, col)
        type(series_t), intent(in) :: s
        integer, intent(in) :: col
        maxabs = maxval(abs(s%v(:, col)))
    end function maxabs

    !> The claims of the paper for the scenes whose output is in outdir.
    subroutine evaluate_claims(outdir, cyl, claims, stat)
        character(len=*), intent(in) :: outdir  !! where the .dat files are
        type(pendulum_t), intent(in) :: cyl     !! the cylinder of the paper's scenes
        type(claim_t), intent(out) :: claims(NCLAIMS)
        type(status_t), intent(out) :: stat     !! ERR_IO when a scene's output is missing
        type(series_t) :: c18, c195, tri, tor
        real(dp) :: r, freq(5), fd
        integer :: nfreq
        call read_series(outdir//'/cylinder_l180.dat', c18, stat)
        if (stat%code == 0) call read_series(outdir//'/cylinder_l195.dat', c195, stat)
        if (stat%code == 0) call read_series(outdir//'/triangle_plate.dat', tri, stat)
        if (stat%code == 0) call read_series(outdir//'/cylinder_torsion.dat', tor, stat)
        if (stat%code /= 0) return
        r = half_period_spread(c18, COL_THETA4)
        claims(1) = claim_t('Fig. 4: torsion proceeds regularly although l'' = 0.9 l', &
            'regular', r, '(max - min)/mean of the half-periods of theta4 (holds if < 0.05)', &
            r < 0.05_dp)
        r = maxabs(c195, COL_THETA1)/maxabs(c18, COL_THETA1)
        claims(2) = claim_t('Figs. 5, 7: a quarter of the length difference reduces max theta1'// &
            ' by about that factor', 'about 0.25', r, &
            'max|theta1| (l''=1.95b) / (l''=1.8b) (holds if 0.15 to 0.4)', &
            r > 0.15_dp .and. r < 0.4_dp)
        r = maxabs(c195, COL_Q)/maxabs(c18, COL_Q)
        claims(3) = claim_t('Figs. 6, 8: a quarter of the length difference reduces max Q'// &
            ' by about that factor', 'about 0.25', r, &
            'max Q (l''=1.95b) / (l''=1.8b) (holds if 0.15 to 0.4)', r > 0.15_dp .and. r < 0.4_dp)
        r = dominant_frequency(c195, COL_THETA1, 0.02_dp, 1.0_dp) &
            /dominant_frequency(c18, COL_THETA1, 0.02_dp, 1.0_dp)
        claims(4) = claim_t('Figs. 5, 7: the smaller tilting comes with a considerably lower'// &
            ' frequency', 'considerable decrease', r, &
            'dominant theta1 frequency (l''=1.95b) / (l''=1.8b) (holds if < 0.8)', r < 0.8_dp)
        ! our explanation: the tilting runs at a natural frequency of the pendulum at rest
        call rest_frequencies(cyl, freq, nfreq, stat)
        if (stat%code /= 0) return
        fd = dominant_frequency(c18, COL_THETA1, 0.02_dp, 1.0_dp)
        r = minval(abs(freq(1:nfreq)/fd - 1.0_dp))
        fd = dominant_frequency(c195, COL_THETA1, 0.02_dp, 1.0_dp)
        r = max(r, minval(abs(freq(1:nfreq)/fd - 1.0_dp)))
        claims(5) = claim_t('(ours, not the paper''s) for l'' = 1.8b and 1.95b alike, tilting'// &
            ' runs at a natural frequency of the pendulum linearised about rest', '-', r, &
            'largest relative distance of the dominant theta1 frequency from the nearest'// &
            ' natural frequency (holds if < 0.03)', r < 0.03_dp)
        r = half_period_spread(tri, COL_THETA4)
        claims(6) = claim_t('Fig. 10: misalignment of principal axes hardly disturbs torsion', &
            'not very much', r, &
            '(max - min)/mean of the half-periods of theta4 (holds if < 0.05)', r < 0.05_dp)
        r = maxabs(tri, COL_THETA1)/maxabs(c18, COL_THETA1)
        claims(7) = claim_t('Figs. 11, 5: the plate''s tilting is no more violent than with'// &
            ' a 10% length difference', 'no more violent', r, &
            'max|theta1| plate / cylinder l''=1.8b (holds if <= 1.1: comparable or less)', &
            r <= 1.1_dp)
        r = maxabs(tri, COL_Q)/maxabs(c18, COL_Q)
        claims(8) = claim_t('Figs. 12, 6: the plate''s side-sway is no more violent than with'// &
            ' a 10% length difference', 'no more violent', r, &
            'max Q plate / cylinder l''=1.8b (holds if <= 1.1: comparable or less)', r <= 1.1_dp)
        r = max(maxabs(tor, COL_THETA1), maxabs(tor, COL_Q))
        claims(9) = claim_t('Eqs. (45)-(49): with equal cables and a symmetric body, torsion'// &
            ' is pure (no tilting, no side-sway)', 'exactly 0', r, &
            'max of |theta1| and Q, equal cables (holds if < 1e-8)', r < 1.0e-8_dp)
    end subroutine evaluate_claims

    !> Write OUTDIR/report.md: the table of claims (claim, paper's value, our value, whether
    !! it holds), then each claim with the figures that support it, the stability of torsion
    !! (Figs. 13-16), the elastic cables and the accuracy against run time with theirs.  The
    !! figures are linked as images (plots_link: relative to OUTDIR), every figure that
    !! `make run` draws (report_figures; test `cli: report shows every figure`).
    subroutine write_report(outdir, stat)
        character(len=*), intent(in) :: outdir  !! where the .dat files are and report.md goes
        type(status_t), intent(out) :: stat     !! ERR_IO when an input or the report fails
        type(claim_t) :: claims(NCLAIMS)
        type(figure_t), allocatable :: figs(:)
        integer :: u, k, ios
        character(len=40) :: val
        call evaluate_claims(outdir, pendulum_t(), claims, stat)
        if (stat%code /= 0) return
        figs = report_figures()
        call atomic_open(outdir//'/report.md', u, stat)
        if (stat%code /= 0) return
        write (u, '(a)', iostat=ios) '# bifilar: the paper''s claims against our results', '', &
            'Kane & Tseng (1966), Figs. 4-8 and 10-12, measured on the output of the decks in '// &
            '`input/` (`make report`; regenerated by `make run`, which also draws the figures '// &
            'shown below).  Time tau = (g/b'')^(1/2) t.', &
            '', '| claim | paper | measure | ours | holds |', '|---|---|---|---|---|'
        do k = 1, size(claims)
            val = value_text(claims(k)%ours)
            if (ios == 0) write (u, '(a)', iostat=ios) '| '//claims(k)%what//' | '// &
                claims(k)%paper//' | '//claims(k)%measure//' | '//trim(val)//' | '// &
                merge('yes', 'no ', claims(k)%holds)//' |'
        end do
        if (.not. claims(4)%holds .and. ios == 0) write (u, '(a)', iostat=ios) '', &
            'Claim 4 is not reproduced: in our runs the dominant tilting frequency '// &
            'is the same for both cable differences (it is a natural frequency of the pendulum '// &
            'at rest, claim 5), while its amplitude falls by the paper''s factor.'
        if (ios == 0) write (u, '(a)', iostat=ios) '', '## The claims beside their figures'
        do k = 1, size(claims)
            val = value_text(claims(k)%ours)
            if (ios == 0) write (u, '(a)', iostat=ios) '', '### '//itoa(k)//'. '// &
                claims(k)%what, '', 'Paper: '//claims(k)%paper//'; ours: '//trim(val)//' ('// &
                claims(k)%measure//'): '//trim(merge('holds        ', 'does not hold', &
                claims(k)%holds))//'.'
            call figure_lines(k)
        end do
        if (ios == 0) call stability_lines(outdir, u, ios)
        call figure_lines(-1)
        if (ios == 0) call elastic_lines(outdir, u, ios)
        call figure_lines(-2)
        if (ios == 0) write (u, '(a)', iostat=ios) '', '## Accuracy against run time', '', &
            'Error against CPU time of LSODA (rtol 1e-3 ... 1e-12) and fixed-step RK4 on the '// &
            'paper''s model (`input/work_precision_cylinder.nml`) and the elastic model '// &
            '(`input/work_precision_elastic.nml`); doc/work_precision.md.'
        call figure_lines(-3)
        if (ios == 0) write (u, '(a)', iostat=ios) '', '## The moment of inertia from a record', &
            '', 'The fit of `input/identify_record.nml` (analysis identify: I1, the damping '// &
            'and the release amplitude from a 30 s gyro record of a laboratory rig with '// &
            'unequal cables; doc/identify.md).'
        call figure_lines(-4)
        if (ios == 0) write (u, '(a)', iostat=ios) '', '## The inertia tensor from several '// &
            'hangs', '', 'The fit of `input/tensor_example.nml` (analysis tensor: the six '// &
            'entries of a body''s tensor from nine hangs, each period from the full model of '// &
            'its hang; doc/tensor.md).'
        call figure_lines(-5)
        call atomic_commit(u, outdir//'/report.md', stat, ios)

    contains

        !> The figures of one section, as markdown images side by side.
        subroutine figure_lines(section)
            integer, intent(in) :: section
            integer :: i
            character(len=:), allocatable :: line
            line = ''
            do i = 1, size(figs)
                if (figs(i)%section /= section) cycle
                line = line//'!['//figs(i)%caption//']('//plots_link(outdir, figs(i)%name)//') '
            end do
            if (len(line) > 0 .and. ios == 0) write (u, '(a)', iostat=ios) '', trim(line)
        end subroutine figure_lines

    end subroutine write_report

    !> Every figure that `make run` draws (one per plots/*.gp), with its caption and the
    !! claim or section of the report it supports.
    function report_figures() result(f)
        type(figure_t), allocatable :: f(:)
        f = [figure_t('fig04_torsion', 'Fig. 4: torsion, cylinder, l = 2b, l'' = 1.8b', 1), &
             figure_t('fig05_tilting', 'Fig. 5: tilting, l'' = 1.8b', 2), &
             figure_t('fig07_tilting', 'Fig. 7: tilting, l'' = 1.95b', 2), &
             figure_t('fig06_sway', 'Fig. 6: side-sway, l'' = 1.8b', 3), &
             figure_t('fig08_sway', 'Fig. 8: side-sway, l'' = 1.95b', 3), &
             figure_t('fig05_tilting', 'Fig. 5: tilting, l'' = 1.8b', 4), &
             figure_t('fig07_tilting', 'Fig. 7: tilting, l'' = 1.95b', 4), &
             figure_t('fig05_tilting', 'Fig. 5: tilting, l'' = 1.8b', 5), &
             figure_t('fig07_tilting', 'Fig. 7: tilting, l'' = 1.95b', 5), &
             figure_t('fig10_torsion', 'Fig. 10: torsion, triangular plate', 6), &
             figure_t('fig11_tilting', 'Fig. 11: tilting, triangular plate', 7), &
             figure_t('fig05_tilting', 'Fig. 5: tilting, l'' = 1.8b', 7), &
             figure_t('fig12_sway', 'Fig. 12: side-sway, triangular plate', 8), &
             figure_t('fig06_sway', 'Fig. 6: side-sway, l'' = 1.8b', 8), &
             figure_t('torsion_symmetric', 'Pure torsion on equal cables: theta4 and theta2', 9), &
             figure_t('fig13_multipliers_unstable', 'Fig. 13: Floquet multipliers, unstable', -1), &
             figure_t('fig14_unstable_tilting', 'Fig. 14: unstable tilting', -1), &
             figure_t('fig15_multipliers_stable', 'Fig. 15: Floquet multipliers, stable', -1), &
             figure_t('fig16_stable_tilting', 'Fig. 16: stable tilting', -1), &
             figure_t('chart_box', 'Stability chart of the parallelepiped', -1), &
             figure_t('box_design_design', 'Rig design of the parallelepiped', -1), &
             figure_t('elastic_vs_kane', 'theta1, elastic cables against the paper''s', -2), &
             figure_t('work_precision', 'Work-precision, the paper''s model', -3), &
             figure_t('work_precision_elastic', 'Work-precision, elastic cables', -3), &
             figure_t('identify_record.identify', 'A gyro record and the fitted model', -4), &
             figure_t('identify_periods.identify', 'Timed periods against amplitude', -4), &
             figure_t('tensor', 'Each hang''s vertical moment against the fitted tensor''s', -5)]
    end function report_figures

    !> The link from OUTDIR/report.md to plots/NAME.png (plots/ in the working folder, where
    !! `make run` draws): '../plots/NAME.png' for OUTDIR = output; an absolute path when
    !! OUTDIR is absolute or climbs with '..'.
    function plots_link(outdir, name) result(link)
        character(len=*), intent(in) :: outdir      !! folder of report.md
        character(len=*), intent(in) :: name        !! figure name, without .png
        character(len=:), allocatable :: link
        character(len=:), allocatable :: up, cwd
        integer :: i, i0
        logical :: climbs
        up = ''
        climbs = len(outdir) == 0
        if (.not. climbs) climbs = outdir(1:1) == '/'
        i0 = 1
        do i = 1, len(outdir) + 1
            if (i <= len(outdir)) then
                if (outdir(i:i) /= '/') cycle
            end if
            if (i > i0) then
                if (outdir(i0:i - 1) == '..') climbs = .true.
                if (outdir(i0:i - 1) /= '.') up = up//'../'
            end if
            i0 = i + 1
        end do
        if (climbs) then
            cwd = working_folder()
            link = cwd//'/plots/'//name//'.png'
        else
            link = up//'plots/'//name//'.png'
        end if
    end function plots_link

    !> The process's working folder (getcwd(3)); '.' when unknown.
    function working_folder() result(w)
        use, intrinsic :: iso_c_binding, only: c_char, c_size_t, c_ptr, c_associated, &
            c_null_char
        character(len=:), allocatable :: w
        interface
            type(c_ptr) function c_getcwd(buf, size) bind(C, name='getcwd')
                import :: c_char, c_size_t, c_ptr
                character(kind=c_char), dimension(*), intent(out) :: buf
                integer(c_size_t), value :: size
            end function c_getcwd
        end interface
        character(kind=c_char, len=4096) :: buf
        integer :: n
        buf = ''
        if (.not. c_associated(c_getcwd(buf, int(len(buf), c_size_t)))) then
            w = '.'
            return
        end if
        n = index(buf, c_null_char) - 1
        if (n < 0) n = len_trim(buf)
        w = buf(1:n)
    end function working_folder

    !> A claim's value for the report: f14.3 from 1e-3 up, sci (E kept) below.
    function value_text(x) result(val)
        real(dp), intent(in) :: x
        character(len=40) :: val
        val = sci(x, 3)
        if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e9_dp) write (val, '(f14.3)') x
        val = adjustl(val)
    end function value_text

    !> Figs. 13-16: the Floquet results and the tilting of the parallelepiped scenes, for the
    !! output files present in outdir.
    subroutine stability_lines(outdir, u, ios)
        character(len=*), intent(in) :: outdir
        integer, intent(in) :: u                !! open report file
        integer, intent(inout) :: ios           !! iostat of the writes
        character(len=20), parameter :: decks(3) = [character(len=20) :: 'box_unstable', &
            'box_stable', 'box_tall_floquet']
        character(len=*), parameter :: figs(3) = [character(len=14) :: 'Figs. 13, 14', &
            'Figs. 15, 16', 'Fig. 13 order']
        real(dp) :: mmod, per, th1, rl, ur, ml, am
        logical :: have_f, have_s, have_d, have_u, have_a
        integer :: k
        character(len=200) :: buf
        write (u, '(a)', iostat=ios) '', '## Stability of torsion (Figs. 13-16)', '', &
            'Paper: the unstable suspension has a largest Floquet multiplier of modulus 2643 '// &
            'at 45 degrees; from theta1 = 0.01 rad its tilting grows dramatically (Fig. 14), '// &
            'the stable one''s stays small (Fig. 16).  Our parallelepipeds: doc/paper.md.', '', &
            '| deck | figures | period t* | largest modulus | stable | max abs theta1 (rad) '// &
            'from theta1(0) = 0.01 |', '|---|---|---|---|---|---|'
        do k = 1, size(decks)
            call read_kv(outdir//'/'//trim(decks(k))//'.floquet', 'max_modulus', mmod, have_f)
            call read_kv(outdir//'/'//trim(decks(k))//'.floquet', 'period', per, have_f)
            call read_kv(outdir//'/'//trim(decks(k))//'.summary', 'max_abs_theta1', th1, have_s)
            if (.not. have_f) cycle
            write (buf, '(a,f8.4,a)') ' | ', per, ' | '//sci(mmod, 4)//' | '// &
                merge('yes', 'no ', mmod <= 1.0_dp + 1.0e-6_dp)//' | '
            if (have_s) then
                write (buf(len_trim(buf) + 2:), '(f8.4,a)') th1, ' |'
            else
                buf = trim(buf)//' (no simulation) |'
            end if
            if (ios == 0) write (u, '(a)', iostat=ios) '| '//trim(decks(k))//' | '// &
                trim(figs(k))//trim(buf)
        end do
        ! the paper's closing advice automated (analysis design)
        call read_kv(outdir//'/box_design.design', 'recommended_l', rl, have_d)
        call read_kv(outdir//'/box_design.design', 'predicted_u_I1_rel', ur, have_u)
        call read_kv(outdir//'/box_design.design', 'stable_margin_l', ml, have_s)
        call read_kv(outdir//'/box_design.design', 'amplitude_max', am, have_a)
        if (all([have_d, have_u, have_s, have_a]) .and. ios == 0) write (u, '(a)', &
            iostat=ios) '', 'The paper''s advice, "use the stability analysis for various '// &
            'combinations of b and l until one is found that does not lead to a prediction '// &
            'of instability", automated (`input/box_design.nml`, the block with b'' = 0.2 m; '// &
            'doc/design.md): recommended l = l'' = '//sci(rl, 4)//' m, stable at '// &
            'every amplitude up to '//sci(am, 3)//' degrees, '//sci(ml, 3)//' m from the '// &
            'nearest unstable band, predicted u(I1)/I1 = '//sci(ur, 3)//'.'
    end subroutine stability_lines

    !> The elastic-cable model against the paper's (cylinder_l180_elastic against
    !! cylinder_l180, same start and output grid), when both outputs are present: the largest
    !! differences in theta1, theta4 and Q, and the largest stretch of AD.
    subroutine elastic_lines(outdir, u, ios)
        character(len=*), intent(in) :: outdir
        integer, intent(in) :: u                !! open report file
        integer, intent(inout) :: ios           !! iostat of the writes
        type(series_t) :: sk, se
        type(status_t) :: st1, st2
        real(dp) :: nst
        logical :: found
        integer :: n
        character(len=300) :: buf
        character(len=20) :: tend
        write (u, '(a)', iostat=ios) '', '## Elastic cables against the paper''s model'
        call read_series(outdir//'/cylinder_l180.dat', sk, st1)
        call read_series(outdir//'/cylinder_l180_elastic.dat', se, st2)
        n = 0
        if (st1%code == 0 .and. st2%code == 0) n = min(size(sk%v, 1), size(se%v, 1))
        if (n >= 2) then
            if (maxval(abs(sk%v(1:n, 1) - se%v(1:n, 1))) > 1.0e-9_dp) n = 0
        end if
        if (n < 2) then
            if (ios == 0) write (u, '(a)', iostat=ios) '', '(no comparison: run '// &
                '`input/cylinder_l180.nml` and `input/cylinder_l180_elastic.nml` into this folder)'
            return
        end if
        write (tend, '(f10.2)') sk%v(n, 1)
        if (ios == 0) write (u, '(a)', iostat=ios) '', &
            '`cylinder_l180_elastic` (`model = ''elastic''`, `&cables` of that deck) against '// &
            '`cylinder_l180` (the paper''s inextensible cables), same start, rows up to tau = '// &
            trim(adjustl(tend))//'.  The difference is O(1/stiffness) (doc/elastic.md).', '', &
            '| max abs diff theta1 (rad) | max abs diff theta4 (rad) | '// &
            'max abs diff Q (b'') | max stretch of AD (b'') | steps |', '|---|---|---|---|---|'
        call read_kv(outdir//'/cylinder_l180_elastic.summary', 'steps', nst, found)
        buf = '| '//trim(num(maxval(abs(sk%v(1:n, 2) - se%v(1:n, 2)))))//' | '// &
            trim(num(maxval(abs(sk%v(1:n, 5) - se%v(1:n, 5)))))//' | '// &
            trim(num(maxval(abs(sk%v(1:n, 12) - se%v(1:n, 12)))))//' | '// &
            trim(num(maxval(abs(se%v(1:n, 17)))))//' | '
        if (found) then
            write (buf(len_trim(buf) + 2:), '(i0,a)') nint(nst), ' |'
        else
            buf = trim(buf)//' - |'
        end if
        if (ios == 0) write (u, '(a)', iostat=ios) trim(buf)
    contains
        function num(x) result(txt)
            real(dp), intent(in) :: x
            character(len=16) :: txt
            txt = sci(x, 3)
        end function num
    end subroutine elastic_lines


end module paper_claims
