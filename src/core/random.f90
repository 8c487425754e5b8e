!> Seeded, repeatable pseudo-random numbers for Monte Carlo (no module state).
!!
!! Generator: xoshiro256** (Blackman & Vigna, "Scrambled linear pseudorandom number
!! generators", ACM TOMS 47, 2021), seeded through splitmix64 (Steele, Lea & Flood,
!! "Fast splittable pseudorandom number generators", OOPSLA 2014), written here from those
!! descriptions.  Fortran has no unsigned integers and signed overflow is not defined, so
!! every 64-bit operation that must wrap modulo 2**64 (addition, multiplication by a
!! constant) is done on 32-bit halves with bit operations only: the results are the
!! generators' published sequences, on any compiler and with any flags.
!!
!! Streams: `rng_stream(seed, k)` gives the k-th stream of a seed, its state hashed from
!! (seed, k) by splitmix64.  A Monte Carlo sample k drawn from its own stream is the same
!! number whichever thread, rank or order computes it, so serial, OpenMP and MPI runs give
!! identical results.
module random
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp, pi
    implicit none
    private

    !> The state of one generator.
    type, public :: rng_t
        integer(int64) :: s(4) = [1_int64, 2_int64, 3_int64, 4_int64]
    end type rng_t

    public :: rng_stream, rng_from_word, rng_next, rng_uniform, rng_normal, splitmix64

    integer(int64), parameter :: LOW32 = 4294967295_int64          !! 2**32 - 1
    !> splitmix64 constants, written as the signed integers with the same 64 bits
    !! (0x9E3779B97F4A7C15, 0xBF58476D1CE4E5B9, 0x94D049BB133111EB)
    integer(int64), parameter :: GOLDEN = -7046029254386353131_int64
    integer(int64), parameter :: MIX1 = -4658895280553007687_int64
    integer(int64), parameter :: MIX2 = -7723592293110705685_int64

contains

    !> The generator of stream k of `seed` (any integers; different (seed, k) give
    !! independent-looking streams).
    pure function rng_stream(seed, k) result(g)
        integer, intent(in) :: seed             !! user seed
        integer, intent(in) :: k                !! stream number (e.g. the sample index)
        type(rng_t) :: g
        integer(int64) :: x
        ! one 64-bit word from (seed, k), then four splitmix64 outputs as the state
        x = ior(shiftl(int(seed, int64), 32), iand(int(k, int64), LOW32))
        g = rng_from_word(splitmix64(x))
    end function rng_stream

    !> The generator seeded from one 64-bit word as its authors recommend: the state is the
    !! next four outputs of splitmix64 started at x0.
    pure function rng_from_word(x0) result(g)
        integer(int64), intent(in) :: x0        !! seed word
        type(rng_t) :: g
        integer(int64) :: x
        integer :: i
        x = x0
        do i = 1, 4
            x = add64(x, GOLDEN)
            g%s(i) = mix(x)
        end do
        if (all(g%s == 0_int64)) g%s(1) = 1_int64   ! the all-zero state is a fixed point
    end function rng_from_word

    !> splitmix64 of x: the output for the state x + golden gamma (a 64-bit hash).
    pure integer(int64) function splitmix64(x) result(z)
        integer(int64), intent(in) :: x         !! input word
        z = mix(add64(x, GOLDEN))
    end function splitmix64

    !> splitmix64's output function (the 64-bit finaliser).
    pure integer(int64) function mix(x) result(z)
        integer(int64), intent(in) :: x
        z = mul64(ieor(x, shiftr(x, 30)), MIX1)
        z = mul64(ieor(z, shiftr(z, 27)), MIX2)
        z = ieor(z, shiftr(z, 31))
    end function mix

    !> The next 64-bit output of xoshiro256** (advances g).
    subroutine rng_next(g, r)
        type(rng_t), intent(inout) :: g         !! generator
        integer(int64), intent(out) :: r        !! 64 random bits
        integer(int64) :: t
        r = times9(ishftc(times5(g%s(2)), 7))
        t = shiftl(g%s(2), 17)
        g%s(3) = ieor(g%s(3), g%s(1))
        g%s(4) = ieor(g%s(4), g%s(2))
        g%s(2) = ieor(g%s(2), g%s(3))
        g%s(1) = ieor(g%s(1), g%s(4))
        g%s(3) = ieor(g%s(3), t)
        g%s(4) = ishftc(g%s(4), 45)
    end subroutine rng_next

    !> A uniform deviate in (0, 1]: the top 53 bits, plus one, times 2**-53.
    function rng_uniform(g) result(u)
        type(rng_t), intent(inout) :: g         !! generator
        real(dp) :: u
        integer(int64) :: r
        call rng_next(g, r)
        u = real(shiftr(r, 11) + 1_int64, dp)*2.0_dp**(-53)
    end function rng_uniform

    !> A standard normal deviate (Box-Muller from two uniforms; always two draws, so a
    !! stream's k-th normal does not depend on the values before it).
    function rng_normal(g) result(z)
        type(rng_t), intent(inout) :: g         !! generator
        real(dp) :: z
        real(dp) :: u1, u2
        u1 = rng_uniform(g)
        u2 = rng_uniform(g)
        z = sqrt(-2.0_dp*log(u1))*cos(2.0_dp*pi*u2)
    end function rng_normal

    ! ---------------------------------------------------------------- wrapping arithmetic

    !> a + b modulo 2**64, on 32-bit halves (no signed overflow).
    pure elemental integer(int64) function add64(a, b) result(c)
        integer(int64), intent(in) :: a, b
        integer(int64) :: lo, hi
        lo = iand(a, LOW32) + iand(b, LOW32)                       ! < 2**33
        hi = iand(shiftr(a, 32) + shiftr(b, 32) + shiftr(lo, 32), LOW32)
        c = ior(shiftl(hi, 32), iand(lo, LOW32))
    end function add64

    !> a * b modulo 2**64 by shift-and-add over the bits of b.
    pure integer(int64) function mul64(a, b) result(c)
        integer(int64), intent(in) :: a, b
        integer :: i
        c = 0_int64
        do i = 0, 63
            if (btest(b, i)) c = add64(c, shiftl(a, i))
        end do
    end function mul64

    pure integer(int64) function times5(a) result(c)
        integer(int64), intent(in) :: a
        c = add64(shiftl(a, 2), a)
    end function times5

    pure integer(int64) function times9(a) result(c)
        integer(int64), intent(in) :: a
        c = add64(shiftl(a, 3), a)
    end function times9

end module random
