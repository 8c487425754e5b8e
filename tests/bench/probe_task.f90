!> A sweep task with known values, for the tests of the sweep engine (suite sweep, in the
!! test program and, over MPI ranks, in tests/sweep_probe.f90).
!!
!! Point i has the values [i, sqrt(i), 1 where rank 0 computed it (0 elsewhere), the OpenMP
!! threads of its rank]; a point costs `i mod 7` times `nap` microseconds of sleep (costs
!! that differ, as a chart's do).  Modes: `ok`, `fail_worker` (points from n/2 on fail on
!! the ranks other than 0), `fail_rank0` (points from n/2 on fail on rank 0), `fail_at`
!! (point `at` fails wherever it is computed), `special` (the values of point i are the
!! special doubles of `special_value`, to check that checkpoints keep every bit).
!! Values read back from a checkpoint are all accepted (`accepts`), unless `strict`: then
!! only point i's own sqrt(i) in the second value, with every value finite.
module probe_task
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    use finite, only: finite_bits
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_NUMERIC
    use text, only: itoa
    use sweep_engine, only: sweep_task_t
    !$ use omp_lib, only: omp_get_max_threads
    implicit none
    private

    public :: special_value

    !> The probe: see the module's notes.
    type, extends(sweep_task_t), public :: probe_task_t
        character(len=16) :: mode = 'ok'
        integer :: n = 0                        !! points of the sweep
        integer :: rank0 = 0                    !! 1 on rank 0
        integer :: at = 0                       !! the point that fails (mode fail_at)
        integer :: nap = 1000                   !! microseconds of sleep per unit of cost
        real(dp) :: shift = 0.0_dp              !! added to the first value (tells runs apart)
        logical :: strict = .false.             !! accepts only the probe's own values
    contains
        procedure :: compute => probe_compute
        procedure :: accepts => probe_accepts
    end type probe_task_t

    interface
        integer(c_int) function c_usleep(usec) bind(C, name='usleep')
            import :: c_int
            integer(c_int), value :: usec
        end function c_usleep
    end interface

contains

    !> Values of point i read back from a checkpoint: any (the special values included),
    !! or when strict only finite ones with sqrt(i) second.
    logical function probe_accepts(self, i, values) result(ok)
        class(probe_task_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: values(:)
        ok = .true.
        if (.not. self%strict) return
        ok = all(finite_bits(values)) .and. size(values) == 4
        if (ok) ok = values(2) == sqrt(real(i, dp))
    end function probe_accepts

    subroutine probe_compute(self, i, values, stat)
        class(probe_task_t), intent(in) :: self
        integer, intent(in) :: i                    !! point
        real(dp), intent(out) :: values(:)          !! 4 values
        type(status_t), intent(out) :: stat
        integer(c_int) :: rc
        integer :: nt
        stat%code = STATUS_OK
        nt = 1
        !$ nt = omp_get_max_threads()
        if (self%nap > 0) rc = c_usleep(int(self%nap*mod(i, 7), c_int))
        values = [real(i, dp) + self%shift, sqrt(real(i, dp)), real(self%rank0, dp), real(nt, dp)]
        select case (trim(self%mode))
        case ('fail_worker')
            if (self%rank0 == 0 .and. 2*i >= self%n) call set_error(stat, ERR_NUMERIC, &
                'probe point '//itoa(i)//' failed on a worker')
        case ('fail_rank0')
            if (self%rank0 == 1 .and. 2*i >= self%n) call set_error(stat, ERR_NUMERIC, &
                'probe point '//itoa(i)//' failed on rank 0')
        case ('fail_at')
            if (i == self%at) call set_error(stat, ERR_NUMERIC, 'probe point '//itoa(i)// &
                                             ' failed')
        case ('special')
            values = [special_value(i), special_value(i + 1), special_value(i + 2), &
                      special_value(i + 3)]
        end select
    end subroutine probe_compute

    !> Doubles whose text would not survive a careless format: -0, the smallest subnormal,
    !! the largest finite, 1 + eps, pi, 1/3, infinity, a quiet NaN (cycled by k).
    function special_value(k) result(x)
        integer, intent(in) :: k
        real(dp) :: x
        select case (mod(k, 8))
        case (0)
            x = -0.0_dp
        case (1)
            x = tiny(1.0_dp)*epsilon(1.0_dp)
        case (2)
            x = huge(1.0_dp)
        case (3)
            x = 1.0_dp + epsilon(1.0_dp)
        case (4)
            x = 4.0_dp*atan(1.0_dp)
        case (5)
            x = 1.0_dp/3.0_dp
        case (6)
            x = ieee_value(1.0_dp, ieee_positive_inf)
        case default
            x = ieee_value(1.0_dp, ieee_quiet_nan)
        end select
    end function special_value

end module probe_task
