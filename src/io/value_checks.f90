!> The checks of a deck's values that every group shares: finite, positive, within the
!! ranges every dimensional value and every ratio keeps, a known word, a standard
!! uncertainty inside its input's domain.  Each records the first problem as an ERR_DECK
!! status naming the group, the variable and its value, what is wrong and what is allowed
!! ('&grp var = value: what; allowed: ...'), and does nothing when the status already
!! carries one.
module value_checks
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: rshort, sci, lower, commas, clip
    implicit none
    private

    !> Every dimensional value (lengths, g, mass, moments of inertia) lies in
    !! DIM_MIN .. DIM_MAX, in any units: no product of them over- or underflows.
    real(dp), parameter, public :: DIM_MIN = 1.0e-100_dp, DIM_MAX = 1.0e100_dp
    !> The scale-free ratios: b, l, l' over b' in RATIO_MIN .. RATIO_MAX; r and |sway_depth|
    !! over b' at most RATIO_MAX.
    real(dp), parameter, public :: RATIO_MIN = 1.0e-3_dp, RATIO_MAX = 1.0e3_dp
    !> Largest |angle| (rad) of tilt, theta, lambda; angles are reduced modulo 2 pi.
    real(dp), parameter, public :: ANGLE_MAX = 1.0e6_dp
    real(dp), parameter, public :: RTOL_MIN = 1.0e-14_dp    !! smallest relative tolerance

    public :: bad, finite, positive, dimensional, over_b_prime, angle, in_domain, check_word

contains

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
                 rshort(six_digits(merge(x - 5.0_dp*u, x + 5.0_dp*u, .not. low_ok)))//', outside '//dom// &
                 ' (a Monte Carlo would draw such values, the budget step there)', &
                 '0 <= '//uname//' < '//rshort(six_digits(umax))//' for '//xname//' = '//rshort(x)// &
                 ' (a fifth of the distance to the edge)')
    end subroutine in_domain

    !> A computed value as a reader wants it: rounded to six significant digits (a bound of
    !! 0.02 reads 0.02, not 0.019999999999998862).
    pure real(dp) function six_digits(v)
        real(dp), intent(in) :: v
        character(len=32) :: buf
        integer :: ios
        six_digits = v
        if (.not. ieee_is_finite(v) .or. v == 0.0_dp) return
        write (buf, '(es20.5e3)', iostat=ios) v
        if (ios == 0) read (buf, *, iostat=ios) six_digits
        if (ios /= 0) six_digits = v
    end function six_digits

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

    !> Check that a string value is one of the blank-separated words of `allowed`.
    subroutine check_word(stat, grp, var, val, allowed)
        type(status_t), intent(inout) :: stat       !! ERR_DECK when val is not allowed
        character(len=*), intent(in) :: grp, var, val, allowed
        if (index(' '//allowed//' ', ' '//lower(trim(adjustl(val)))//' ') > 0 .and. &
            len_trim(val) > 0 .and. index(trim(adjustl(val)), ' ') == 0) return
        call set_error(stat, ERR_DECK, '&'//grp//' '//var//' = '''//clip(trim(val))// &
                       ''': unknown '//var//'; allowed: '//commas(allowed))
    end subroutine check_word

end module value_checks
