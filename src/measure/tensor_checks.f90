!> What a fitted inertia tensor must obey before analysis tensor returns it, and what the
!! hangs' directions must be said about.
!!
!! * A rigid body's principal moments are positive and obey the triangle inequalities,
!!   I_max <= I_a + I_b (equality: a lamina).  A tensor that is not positive definite is
!!   refused; one whose largest moment exceeds the sum of the two others by more than
!!   TRIANGLE_MARGIN (the margin identify uses) is refused, by less a warning.
!! * The body's size (&body size = d, the diameter of a sphere that holds the body): about
!!   the sphere's centre O, int |r - O|^2 dm <= m d^2/4, and about the mass centre it is
!!   smaller still, so the principal moments sum to at most m d^2/2 (twice that integral)
!!   and none exceeds m d^2/4.  Beyond that, refused.
!! * The deck's &body inertia (start values, when given): a fitted tensor whose trace is
!!   more than START_FACTOR times theirs, or less than 1/START_FACTOR, is refused: such a
!!   factor is a counting or unit mistake (N-cycle totals without their cycles column make
!!   the moments N^2 times too large, a mass in g 1000 times), not a start value's error.
!! * Directions: two hangs whose up directions (u and -u count as one) lie within
!!   NEAR_PARALLEL_DEG of each other are named in a warning: they count as one direction of
!!   the six the tensor needs.
!!
!! Refusals are ERR_MODEL (exit 4) statuses of one line naming the variable, what is wrong,
!! the likely cause and what is allowed.  No routine stops.
module tensor_checks
    use kinds, only: dp, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_MODEL
    use text, only: itoa, sci, fixed, rshort
    use measurement, only: hang_t
    implicit none
    private

    public :: check_moments, near_parallel_hangs

    !> The margin of the triangle inequality beyond which a tensor is refused (identify's).
    real(dp), parameter, public :: TRIANGLE_MARGIN = 1.1_dp
    !> The factor between the fitted trace and the start values' beyond which it is refused.
    real(dp), parameter, public :: START_FACTOR = 30.0_dp
    !> Two hangs' up directions closer than this (degrees) are named in a warning.
    real(dp), parameter, public :: NEAR_PARALLEL_DEG = 1.0_dp

    !> The likely causes of moments too large, as a refusal names them.
    character(len=*), parameter :: CAUSES_HIGH = 'likely: totals of N cycles typed as '// &
        'periods (a cycles column missing makes the moments N^2 times too large), times in '// &
        'other units than s, a mass or lengths in other units than the deck''s'

contains

    !> The physical checks of fitted principal moments w (ascending) of a body of mass
    !! `mass` (see the module header): size > 0 the deck's &body size, start(3) the deck's
    !! &body inertia when start_given.  warning: '' or one line.
    subroutine check_moments(w, mass, size, start, start_given, warning, stat)
        real(dp), intent(in) :: w(3)            !! principal moments, ascending
        real(dp), intent(in) :: mass            !! the body's mass
        real(dp), intent(in) :: size            !! &body size (0: not given)
        real(dp), intent(in) :: start(3)        !! &body inertia
        logical, intent(in) :: start_given      !! &body inertia given
        character(len=:), allocatable, intent(out) :: warning
        type(status_t), intent(out) :: stat     !! ERR_MODEL
        real(dp) :: tr, trs, bound
        character(len=:), allocatable :: mom
        stat%code = STATUS_OK
        warning = ''
        mom = sci(w(1), 4)//', '//sci(w(2), 4)//', '//sci(w(3), 4)
        if (.not. (w(1) > 0.0_dp)) then
            call set_error(stat, ERR_MODEL, 'tensor: the fitted tensor is not positive '// &
                'definite (principal moments '//mom//'): no rigid body has it; check the '// &
                'directions (up, along) and the periods of the hangs; allowed: a table whose '// &
                'periods a body can give')
            return
        end if
        if (w(3) > TRIANGLE_MARGIN*(w(1) + w(2))) then
            call set_error(stat, ERR_MODEL, 'tensor: the principal moments '//mom//' break '// &
                'the triangle inequality: the largest is '//fixed(w(3)/(w(1) + w(2)), 2)// &
                ' times the sum of the others, beyond the '//rshort(TRIANGLE_MARGIN)// &
                ' no rigid body reaches (a lamina has 1); check the directions and the '// &
                'periods of the hangs; allowed: I_max <= I_a + I_b')
            return
        else if (w(3) > w(1) + w(2)) then
            warning = 'tensor: the principal moments '//mom//' exceed the triangle '// &
                'inequality by '//fixed(100.0_dp*(w(3)/(w(1) + w(2)) - 1.0_dp), 1)// &
                ' % (a lamina reaches I_max = I_a + I_b): check the directions and the '// &
                'periods of the hangs'
        end if
        tr = sum(w)
        if (size > 0.0_dp) then
            bound = 0.5_dp*mass*size**2
            if (tr > bound) then
                call set_error(stat, ERR_MODEL, 'tensor: &body size = '//rshort(size)// &
                    ': the principal moments '//mom//' sum to '//sci(tr, 4)//', more than '// &
                    'mass size^2/2 = '//sci(bound, 4)//' that a body inside a sphere of '// &
                    'diameter size can have (each moment at most mass size^2/4 = '// &
                    sci(0.5_dp*bound, 4)//'); '//CAUSES_HIGH)
                return
            end if
        end if
        if (start_given) then
            trs = sum(start)
            if (tr > START_FACTOR*trs .or. tr < trs/START_FACTOR) then
                call set_error(stat, ERR_MODEL, 'tensor: &body inertia = '// &
                    sci(start(1), 3)//', '//sci(start(2), 3)//', '//sci(start(3), 3)// &
                    ' (start values): the fitted principal moments '//mom//' are '// &
                    factor_text(tr/trs)//' them in sum, beyond the factor '// &
                    rshort(START_FACTOR)//' a start value may be off; '//causes(tr > trs)// &
                    '; allowed: &body inertia within a factor '// &
                    rshort(START_FACTOR)//' of the moments the table gives')
                return
            end if
        end if
    end subroutine check_moments

    !> The likely causes of moments too large (high) or too small.
    function causes(high) result(s)
        logical, intent(in) :: high
        character(len=:), allocatable :: s
        if (high) then
            s = CAUSES_HIGH
            return
        end if
        s = 'likely: periods typed per half swing, times in other units than s, a mass or '// &
            'lengths in other units than the deck''s'
    end function causes

    !> 'N times' or '1/N of'.
    function factor_text(f) result(s)
        real(dp), intent(in) :: f
        character(len=:), allocatable :: s
        if (f >= 1.0_dp) then
            s = sci(f, 3)//' times'
        else
            s = '1/'//sci(1.0_dp/f, 3)//' of'
        end if
    end function factor_text

    !> Pairs of hangs (distinct ids) whose up directions lie within NEAR_PARALLEL_DEG of
    !! each other (u and -u as one): a warning line naming them ('' when none).
    function near_parallel_hangs(hangs, what) result(warning)
        type(hang_t), intent(in) :: hangs(:)    !! the hangs
        character(len=*), intent(in) :: what    !! the table, for the message
        character(len=:), allocatable :: warning
        integer :: i, j, n
        real(dp) :: c, ang
        character(len=:), allocatable :: pairs
        pairs = ''
        n = 0
        do i = 1, size(hangs)
            do j = i + 1, size(hangs)
                if (hangs(i)%id == hangs(j)%id) cycle
                c = min(1.0_dp, abs(dot_product(hangs(i)%up, hangs(j)%up)))
                ang = acos(c)/deg
                if (ang >= NEAR_PARALLEL_DEG) cycle
                n = n + 1
                if (n <= 4) then
                    if (len(pairs) > 0) pairs = pairs//'; '
                    pairs = pairs//'hangs '//itoa(hangs(i)%id)//' (line '// &
                        itoa(hangs(i)%line)//') and '//itoa(hangs(j)%id)//' (line '// &
                        itoa(hangs(j)%line)//'), '//fixed(ang, 2)//' deg'
                end if
            end do
        end do
        warning = ''
        if (n == 0) return
        if (n > 4) pairs = pairs//' and '//itoa(n - 4)//' more'
        warning = 'tensor: '//what//': up directions less than '// &
            rshort(NEAR_PARALLEL_DEG)//' deg apart (u and -u count as one): '//pairs// &
            '; each pair counts as one direction of the six the tensor needs'
    end function near_parallel_hangs

end module tensor_checks
