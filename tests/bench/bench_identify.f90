!> Work units for the identify figures of `make bench` (tests/bench/speed.sh):
!! each mode repeats one unit n times, so that its instruction count is the difference of
!! two runs under `valgrind --tool=callgrind` (n and 0 repetitions) over n, and its CPU time
!! the cpu_time of a run over n.
!!
!!   bench_identify periods N       one inversion of the three periods of
!!                                  input/identify_periods.nml (symmetric rig: exact torsion)
!!   bench_identify periods_asym N  the same periods on that rig with l' = 1.18 m and the mass
!!                                  centre 0.5 mm off (periods of the full model, simulated)
!!   bench_identify record N        the fit of input/identify_record_swing.dat (30 s, 100 Hz,
!!                                  3001 samples) with three parameters, I1 c_v c_q, and its
!!                                  first-order budget (identify_record)
!!   bench_identify record_differences N  the same with &integration sensitivities =
!!                                  'differences' (the Jacobian and the budget's input
!!                                  sensitivities from differences of whole runs)
!!   bench_identify rates N         the fit of a 3-axis gyro record (30 s, 100 Hz; made here:
!!                                  the laboratory rig of input/identify_record.nml released
!!                                  with 2 degrees of tilt and 1 cm of sway, noise and bias)
!!                                  with six parameters, I1 I2 I3 cg_depth tilt sway, and the
!!                                  three axes' biases, and its first-order budget
!!   bench_identify rates_p N       mode rates, and after the fits each parameter's name,
!!                                  estimate and first-order u (es24.16), a line each (to
!!                                  compare two builds' results digit by digit)
!!   bench_identify mc N            N Monte Carlo samples from the periods of
!!                                  input/identify_periods.nml (one unit = one sample; OpenMP
!!                                  threads as set, OMP_NUM_THREADS)
!!
!! Prints one line: `MODE units cpu_seconds_per_unit checksum`.
program bench_identify
    use kinds, only: dp
    use status, only: status_t
    use bench_args, only: int_arg, need
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, accuracy_of, read_record, deck_inputs
    use period_inversion, only: input_u_t, period_fit_t, invert_periods, period_monte_carlo
    use identify, only: identify_result_t, identify_record
    use records, only: record_t
    use rig, only: rig_t, start_t, accuracy_t
    use record_fit, only: record_model
    use random, only: rng_t, rng_stream, rng_normal
    implicit none
    character(len=256) :: mode
    type(deck_t) :: d
    type(status_t) :: st
    type(period_fit_t) :: f
    type(input_u_t) :: u
    type(record_t) :: rec
    type(identify_result_t) :: res
    real(dp) :: t0, t1, sumck, mean, sdev
    integer :: n, k, units
    call get_command_argument(1, mode)
    n = int_arg(2)
    sumck = 0.0_dp
    units = n
    select case (trim(mode))
    case ('periods', 'periods_asym', 'mc')
        call read_deck('input/identify_periods.nml', d, st)
        call need(st, 'bench_identify')
        if (trim(mode) == 'periods_asym') then
            d%suspension%l_prime = 1.18_dp
            d%body%lambda = 0.64_dp
        end if
        associate (m => d%measurement)
            u = input_u_t(period=m%u_period, amplitude=m%u_amplitude, mass=m%u_mass, l=m%u_l, &
                          l_prime=m%u_l_prime, b=m%u_b, b_prime=m%u_b_prime, g=m%u_g)
        end associate
        call cpu_time(t0)
        if (trim(mode) == 'mc') then
            if (n >= 2) then
                call period_monte_carlo(d, rig_of(d), accuracy_of(d), deck_inputs(d, .false.), &
                                        d%measurement%periods(1:3), &
                                        d%measurement%amplitudes(1:3), u, 0.0512_dp, n, &
                                        d%measurement%seed, mean, sdev, st)
                call need(st, 'bench_identify')
                sumck = sdev
            end if
        else
            do k = 1, n
                call invert_periods(rig_of(d), accuracy_of(d), d%measurement%periods(1:3), &
                                    d%measurement%amplitudes(1:3), u, f, st)
                call need(st, 'bench_identify')
                sumck = sumck + f%i1
            end do
        end if
        call cpu_time(t1)
    case ('record', 'record_differences')
        call read_deck('input/identify_record.nml', d, st)
        call need(st, 'bench_identify')
        if (trim(mode) == 'record_differences') d%integration%sensitivities = 'differences'
        d%measurement%estimate = 'I1 c_v c_q'
        d%measurement%monte_carlo = 0
        call read_record(d, rec, st)
        call need(st, 'bench_identify')
        call cpu_time(t0)
        do k = 1, n
            call identify_record(d, rec, res, st)
            call need(st, 'bench_identify')
            sumck = sumck + res%i1
        end do
        call cpu_time(t1)
    case ('rates', 'rates_p')
        call rates_record()
        call read_deck('build/bench_rates.nml', d, st)
        call need(st, 'bench_identify')
        call cpu_time(t0)
        do k = 1, n
            call identify_record(d, rec, res, st)
            call need(st, 'bench_identify')
            sumck = sumck + res%i1
        end do
        call cpu_time(t1)
        if (trim(mode) == 'rates_p' .and. n > 0) then
            do k = 1, res%np
                write (*, '(a,2es24.16)') res%names(k), res%p(k), res%u_p(k)
            end do
        end if
    case default
        write (*, '(a)') 'usage: bench_identify periods|periods_asym|record|record_differences|'// &
            'rates|rates_p|mc N'
        stop 1
    end select
    write (*, '(a,1x,i0,es14.5,es24.15)') trim(mode), units, (t1 - t0)/max(1, units), sumck
contains
    !> The 3-axis gyro record of mode 'rates' (rec) and its deck (build/bench_rates.nml).
    subroutine rates_record()
        integer, parameter :: NS = 3001
        type(rig_t) :: rg
        type(start_t) :: st0
        type(accuracy_t) :: acc
        type(rng_t) :: g
        real(dp) :: vals(3*NS), axes(3, 3)
        integer :: i, j, io
        rg%b = 0.40_dp
        rg%b_prime = 0.40_dp
        rg%l = 1.20_dp
        rg%l_prime = 1.18_dp
        rg%g = 9.80665_dp
        rg%mass = 3.10_dp
        rg%inertia = [0.0512_dp, 0.0630_dp, 0.0304_dp]
        rg%r = 0.25_dp
        rg%lambda = 0.64_dp
        rg%c_v = 0.0_dp
        rg%c_q = 0.0_dp
        st0%mode = 'raised'
        st0%amplitude = 30.0_dp
        st0%tilt = 2.0_dp*3.141592653589793_dp/180.0_dp
        st0%sway = 0.01_dp/rg%l
        acc%rtol = 1.0e-10_dp
        acc%atol = 1.0e-12_dp
        axes = 0.0_dp
        do i = 1, 3
            axes(i, i) = 1.0_dp
        end do
        allocate (rec%t(NS), rec%v(NS), rec%u(NS), rec%vs(3*NS))
        do i = 1, NS
            rec%t(i) = 0.01_dp*(i - 1)
        end do
        call record_model(rg, st0, acc, rec%t, 0.0_dp, .true., vals, st, axes)
        call need(st, 'bench_identify')
        g = rng_stream(7, 0)
        do j = 1, 3
            do i = 1, NS
                rec%vs((j - 1)*NS + i) = vals((j - 1)*NS + i) + 0.002_dp*j + &
                    0.003_dp*rng_normal(g)
            end do
        end do
        rec%v = -rec%vs(1:NS)
        rec%u = 1.0_dp
        rec%rate = .true.
        rec%units = 'rad/s'
        open (newunit=io, file='build/bench_rates.nml', status='replace', action='write')
        write (io, '(a)') '&scene title = ''3-axis gyro'', analyses = ''identify'' /'
        write (io, '(a)') '&suspension b = 0.40, b_prime = 0.40, l = 1.20, l_prime = 1.18, '// &
            'g = 9.80665 /'
        write (io, '(a)') '&body mass = 3.10, inertia = 0.0502, 0.0670, 0.0284, '// &
            'cg_depth = 0.14, cg_offset = 0.000525 /'
        write (io, '(a)') '&start mode = ''raised'', amplitude = 30.0 /'
        write (io, '(a)') '&integration rtol = 1e-10, atol = 1e-12 /'
        write (io, '(a)') '&measurement record = ''bench_rates.dat'', quantity = ''rates'', '// &
            'estimate = ''I1 I2 I3 cg_depth tilt sway bias'' /'
        close (io)
    end subroutine rates_record

end program bench_identify
