!> The stability analyses of a deck: `floquet` (one amplitude) and `chart` (a grid of two
!! deck parameters), Kane & Tseng (1966) eqs. (45)-(51).
!!
!! Writes OUTDIR/NAME.floquet (key = value lines and the multiplier table) and
!! OUTDIR/NAME.chart.dat (x, y, max_modulus, period), each through a temporary file.
!! The chart runs its points in parallel with OpenMP (OMP_NUM_THREADS is honoured) and
!! reports progress on standard error.
module stability
    use, intrinsic :: iso_fortran_env, only: error_unit
    use kinds, only: dp, deg
    use status, only: status_t
    use geometry, only: pendulum_t
    use deck, only: deck_t, deck_echo
    use simulate, only: make_pendulum
    use floquet, only: floquet_result_t, floquet_analysis, check_torsion_scene
    use output_io, only: atomic_open, atomic_commit, write_kv
    implicit none
    private

    public :: run_floquet, run_chart, set_chart_variable

    !> Sentinel written for chart points where no analysis is possible (not a torsion scene,
    !! cables cannot reach, impossible inertia): never NaN.
    real(dp), parameter, public :: CHART_INVALID = -1.0_dp

contains

    !> Floquet analysis of a deck at &floquet amplitude: OUTDIR/NAME.floquet.
    subroutine run_floquet(d, outdir, res, stat)
        type(deck_t), intent(in) :: d           !! the deck (a torsion scene)
        character(len=*), intent(in) :: outdir  !! output directory
        type(floquet_result_t), intent(out) :: res
        type(status_t), intent(out) :: stat     !! ERR_DECK (not a torsion scene), ERR_NUMERIC
        type(pendulum_t) :: p
        real(dp) :: t0, t1
        integer :: u, k, ivert
        character(len=:), allocatable :: path
        call make_pendulum(d, p, stat)
        if (stat%code /= 0) return
        call check_torsion_scene(p, ivert, stat)
        if (stat%code /= 0) then
            stat%msg = d%name//': analyses = ''floquet'' needs a scene in which pure torsion '// &
                'is an exact motion: '//stat%msg
            return
        end if
        call cpu_time(t0)
        call floquet_analysis(p, d%floquet_amplitude*deg, d%floquet_rtol, d%floquet_segments, &
                              res, stat)
        call cpu_time(t1)
        if (stat%code /= 0) then
            stat%msg = d%name//': floquet: '//stat%msg
            return
        end if
        path = outdir//'/'//d%name//'.floquet'
        call atomic_open(path, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)') '# bifilar Floquet analysis of pure torsion: '//trim(d%title)
        write (u, '(a)') '# period in units of tau = sqrt(g/b'') t; multipliers of the '// &
            'monodromy matrix H(t*) of eq. (51)'
        call deck_echo(d, u)
        call write_kv(u, 'period', res%period)
        call write_kv(u, 'max_modulus', res%max_modulus)
        call write_kv(u, 'stable', res%stable)
        call write_kv(u, 'amplitude_deg', d%floquet_amplitude)
        call write_kv(u, 'segments', d%floquet_segments)
        call write_kv(u, 'rtol', d%floquet_rtol)
        call write_kv(u, 'orbit_closure', res%orbit_closure)
        call write_kv(u, 'trivial_residual', res%trivial_residual)
        call write_kv(u, 'cpu_seconds', t1 - t0)
        call write_kv(u, 'steps', res%steps)
        call write_kv(u, 'rhs_evaluations', res%rhs_evaluations)
        write (u, '(a)') '# multipliers: re im modulus trivial (trivial: 1 by structure -- '// &
            'time shift, energy, constraint and its rate)'
        do k = 1, size(res%multipliers)
            write (u, '(3es24.15e3,2x,a)') real(res%multipliers(k)), aimag(res%multipliers(k)), &
                abs(res%multipliers(k)), merge('yes', 'no ', res%trivial(k))
        end do
        call atomic_commit(u, path, stat)
    end subroutine run_floquet

    !> Set one chart variable (deck units: l and b over b', amplitude in degrees, r over b',
    !! lambda in radians, inertia_ratio = I3/I1) in p, or the amplitude.
    pure subroutine set_chart_variable(name, value, p, amp_deg)
        character(len=*), intent(in) :: name    !! l, b, amplitude, r, lambda, inertia_ratio
        real(dp), intent(in) :: value
        type(pendulum_t), intent(inout) :: p
        real(dp), intent(inout) :: amp_deg      !! torsion amplitude (degrees)
        select case (trim(name))
        case ('l')
            p%big_l = value
            p%big_lp = value
        case ('b')
            p%big_b = value
        case ('amplitude')
            amp_deg = value
        case ('r')
            p%r = value
        case ('lambda')
            p%lambda = value
        case ('inertia_ratio')
            p%inertia(3) = value*p%inertia(1)
        end select
    end subroutine set_chart_variable

    !> Stability chart over the grid of &chart: OUTDIR/NAME.chart.dat with one row per point,
    !! `x y max_modulus period` (CHART_INVALID where no analysis is possible), a blank line
    !! after each x (gnuplot grid format).
    subroutine run_chart(d, outdir, nstable, wall_seconds, stat)
        type(deck_t), intent(in) :: d           !! the deck
        character(len=*), intent(in) :: outdir  !! output directory
        integer, intent(out) :: nstable         !! number of stable points
        real(dp), intent(out) :: wall_seconds   !! elapsed time of the sweep
        type(status_t), intent(out) :: stat
        type(pendulum_t) :: p0, p
        type(floquet_result_t) :: res
        type(status_t) :: st
        real(dp), allocatable :: xs(:), ys(:), mods(:, :), pers(:, :)
        real(dp) :: amp
        integer :: i, j, k, u, ndone, npts, next_report, c0, c1, crate
        integer :: ivert
        logical :: valid
        character(len=:), allocatable :: path

        call make_pendulum(d, p0, stat)
        if (stat%code /= 0) return
        allocate (xs(d%chart_nx), ys(d%chart_ny), mods(d%chart_nx, d%chart_ny), &
                  pers(d%chart_nx, d%chart_ny))
        do i = 1, d%chart_nx
            xs(i) = d%chart_x_min + (d%chart_x_max - d%chart_x_min)*(i - 1)/(d%chart_nx - 1)
        end do
        do j = 1, d%chart_ny
            ys(j) = d%chart_y_min + (d%chart_y_max - d%chart_y_min)*(j - 1)/(d%chart_ny - 1)
        end do
        npts = d%chart_nx*d%chart_ny
        ndone = 0
        next_report = max(1, npts/20)
        call system_clock(c0, crate)
        !$omp parallel do schedule(dynamic, 4) default(none) &
        !$omp shared(d, p0, xs, ys, mods, pers, npts, ndone, next_report) &
        !$omp private(k, i, j, p, amp, res, st, valid, ivert)
        do k = 1, npts
            i = mod(k - 1, d%chart_nx) + 1
            j = (k - 1)/d%chart_nx + 1
            p = p0
            amp = d%floquet_amplitude
            call set_chart_variable(d%chart_x, xs(i), p, amp)
            call set_chart_variable(d%chart_y, ys(j), p, amp)
            valid = all(p%inertia > 0.0_dp) .and. p%inertia(1) <= p%inertia(2) + p%inertia(3) &
                    .and. p%inertia(2) <= p%inertia(1) + p%inertia(3) &
                    .and. p%inertia(3) <= p%inertia(1) + p%inertia(2)
            mods(i, j) = CHART_INVALID
            pers(i, j) = CHART_INVALID
            if (valid) then
                call check_torsion_scene(p, ivert, st)
                if (st%code == 0) then
                    call floquet_analysis(p, amp*deg, d%floquet_rtol, d%floquet_segments, res, st)
                    if (st%code == 0) then
                        mods(i, j) = res%max_modulus
                        pers(i, j) = res%period
                    end if
                end if
            end if
            !$omp critical (chart_progress)
            ndone = ndone + 1
            if (ndone >= next_report .and. npts >= 100) then
                write (error_unit, '(a,a,i0,a,i0,a)') d%name, ': chart ', ndone, ' of ', npts, &
                    ' points'
                next_report = next_report + max(1, npts/20)
            end if
            !$omp end critical (chart_progress)
        end do
        !$omp end parallel do
        call system_clock(c1)
        wall_seconds = real(c1 - c0, dp)/real(crate, dp)
        nstable = count(mods >= 0.0_dp .and. mods <= 1.0_dp + 1.0e-6_dp)

        path = outdir//'/'//d%name//'.chart.dat'
        call atomic_open(path, u, stat)
        if (stat%code /= 0) return
        write (u, '(a)') '# bifilar stability chart of pure torsion: '//trim(d%title)
        write (u, '(a)') '# x = '//trim(d%chart_x)//', y = '//trim(d%chart_y)// &
            ' (l, b, r over b''; amplitude in degrees; lambda in rad; inertia_ratio = I3/I1)'
        write (u, '(a,es10.3,a)') '# max_modulus and period = ', CHART_INVALID, &
            ' where pure torsion is not possible (not a torsion scene, cables cannot reach)'
        call deck_echo(d, u)
        write (u, '(a)') '# x y max_modulus period'
        do i = 1, d%chart_nx
            do j = 1, d%chart_ny
                write (u, '(4es24.15e3)') xs(i), ys(j), mods(i, j), pers(i, j)
            end do
            write (u, '(a)') ''
        end do
        call atomic_commit(u, path, stat)
    end subroutine run_chart

end module stability
