!> A tare read from its own output (&measurement tare = 'FILE'): the NAME.identify file
!! that an identify deck of the empty rig or the fixture wrote, with its I1, its budget
!! rows (value, u, sensitivity, contribution), the part of its u measured anew for it
!! (`u_I1_own`, its degrees of freedom `dof_own`, the first `budget_own_rows` rows), the
!! rig it was measured on (`rig_l` ... `rig_g` and their u) and its calibration.
!!
!! The body's I1 is the loaded deck's minus the tare's.  The inputs both runs share (the
!! rig's l, l_prime or a platform's length, b, b_prime, g, and a calibration) carry one
!! error into both: they enter the difference once, with the difference of the two
!! sensitivities (shared_sensitivity), not twice.  The tare's own part (its timings,
!! amplitudes, releases) and its body's inputs (its mass, I2, I3, mass centre) are
!! independent of the loaded run's and enter as rows of their own; the own part keeps its
!! degrees of freedom for Welch-Satterthwaite.  A timing is a reading of one swing: the
!! two runs' timings are different readings, so their errors are independent.
module tare_file
    use kinds, only: dp
    use status, only: status_t, set_error, ERR_DECK
    use text, only: quoted, sci
    use output_io, only: read_kv
    use stats, only: NU_INFINITE
    use budget, only: budget_row_t, ROW_INPUT, ROW_TARE
    implicit none
    private

    !> The rig's constants a tare must share with the loaded run (keys rig_NAME, u_rig_NAME).
    character(len=8), parameter, public :: RIG_KEYS(5) = [character(len=8) :: 'l', 'l_prime', &
        'b', 'b_prime', 'g']

    !> A tare's output, as read.
    type, public :: tare_file_t
        character(len=:), allocatable :: path
        real(dp) :: i1 = 0.0_dp, u_i1 = 0.0_dp
        real(dp) :: u_own = 0.0_dp              !! the part measured anew for it
        real(dp) :: nu_own = NU_INFINITE        !! its degrees of freedom
        integer :: n_own = 0                    !! its first n_own budget rows are that part
        type(budget_row_t), allocatable :: rows(:)
        real(dp) :: rig(5) = 0.0_dp, u_rig(5) = 0.0_dp     !! RIG_KEYS' values and u
        logical :: calibrated = .false.
        real(dp) :: delta_l = 0.0_dp, scale = 1.0_dp        !! its calibration's constants
    end type tare_file_t

    public :: read_tare_file, is_shared_input, shared_sensitivity, check_same_rig, &
              tare_own_rows

contains

    !> Is the budget input `name` one the tare's run shares with the loaded run?
    pure logical function is_shared_input(name)
        character(len=*), intent(in) :: name
        select case (trim(name))
        case ('l', 'l_prime', 'length', 'b', 'b_prime', 'g', 'calibration')
            is_shared_input = .true.
        case default
            is_shared_input = .false.
        end select
    end function is_shared_input

    !> The tare's sensitivity dI1_tare/dx to the shared input `name` (found: it has a row).
    pure subroutine shared_sensitivity(t, name, c, found)
        type(tare_file_t), intent(in) :: t
        character(len=*), intent(in) :: name
        real(dp), intent(out) :: c
        logical, intent(out) :: found
        integer :: j
        c = 0.0_dp
        found = .false.
        do j = t%n_own + 1, size(t%rows)
            if (trim(t%rows(j)%input) /= trim(name)) cycle
            c = t%rows(j)%sensitivity
            found = .true.
            return
        end do
    end subroutine shared_sensitivity

    !> The tare's rows that enter the body's budget apart from the shared inputs: its own
    !! part as one row 'tare: own' (u_own, sensitivity -1), then each row of its body's
    !! inputs as 'tare: NAME' with the opposite sensitivity; kind ROW_TARE.  nu: their
    !! degrees of freedom (the own part's, then infinite).
    pure subroutine tare_own_rows(t, rows, nu)
        type(tare_file_t), intent(in) :: t
        type(budget_row_t), allocatable, intent(out) :: rows(:)
        real(dp), allocatable, intent(out) :: nu(:)
        integer :: j
        rows = [budget_row_t('tare: own', t%i1, t%u_own, -1.0_dp, t%u_own, ROW_TARE)]
        nu = [t%nu_own]
        do j = t%n_own + 1, size(t%rows)
            if (is_shared_input(t%rows(j)%input)) cycle
            rows = [rows, budget_row_t('tare: '//trim(t%rows(j)%input), t%rows(j)%value, &
                    t%rows(j)%u, 0.0_dp - t%rows(j)%sensitivity, t%rows(j)%contribution, ROW_TARE)]
            nu = [nu, NU_INFINITE]
        end do
    end subroutine tare_own_rows

    !> Refuse a tare from another rig: a constant of RIG_KEYS that differs from the loaded
    !! run's (rig, u_rig) by more than twice their combined u (when both u are 0: by more
    !! than 1e-9 of it); a calibration that is not the same.
    subroutine check_same_rig(t, key, rig, u_rig, calibrated, delta_l, scale, stat)
        type(tare_file_t), intent(in) :: t
        character(len=*), intent(in) :: key     !! the deck's words for it
        real(dp), intent(in) :: rig(5), u_rig(5), delta_l, scale
        logical, intent(in) :: calibrated
        type(status_t), intent(inout) :: stat
        integer :: j
        real(dp) :: tol
        do j = 1, 5
            tol = max(2.0_dp*sqrt(u_rig(j)**2 + t%u_rig(j)**2), 1.0e-9_dp*abs(rig(j)))
            if (abs(rig(j) - t%rig(j)) <= tol) cycle
            call set_error(stat, ERR_DECK, key//' = '//quoted(t%path)//': measured on '// &
                'another rig: its '//trim(RIG_KEYS(j))//' = '//sci(t%rig(j), 6)// &
                ', this deck''s '//sci(rig(j), 6)//' (beyond twice their u); allowed: a '// &
                'tare measured on this rig (the same l, l_prime, b, b_prime, g within u), '// &
                'or tare_I1 with its u for a tare measured elsewhere')
            return
        end do
        if (calibrated .neqv. t%calibrated) then
            call set_error(stat, ERR_DECK, key//' = '//quoted(t%path)//': '// &
                trim(merge('this deck has a calibration and the tare none', &
                           'the tare has a calibration and this deck none', calibrated))// &
                '; allowed: both runs with the same &measurement calibration, or neither')
            return
        end if
        if (calibrated .and. (abs(delta_l - t%delta_l) > 1.0e-12_dp*max(1.0_dp, abs(delta_l)) &
                              .or. abs(scale - t%scale) > 1.0e-12_dp*abs(scale))) then
            call set_error(stat, ERR_DECK, key//' = '//quoted(t%path)//': another '// &
                'calibration (scale '//sci(t%scale, 8)//' against this deck''s '// &
                sci(scale, 8)//'); allowed: both runs with the same &measurement calibration')
        end if
    end subroutine check_same_rig

    !> Read the tare's output at `path`; `key` names the deck's variable in messages.  A
    !! missing file, one that is not an identify output, or one without the keys of the
    !! tare (an older version's) is refused (ERR_DECK).
    subroutine read_tare_file(path, key, t, stat)
        character(len=*), intent(in) :: path, key
        type(tare_file_t), intent(out) :: t
        type(status_t), intent(inout) :: stat
        character(len=16), parameter :: KEYS(4) = [character(len=16) :: 'I1', 'u_I1', &
            'u_I1_own', 'budget_own_rows']
        character(len=*), parameter :: ALLOWED = '; allowed: the NAME.identify file that '// &
            'an identify deck of the tare (the empty rig or the fixture) wrote'
        real(dp) :: v(size(KEYS)), x
        logical :: found, ok
        integer :: u, ios, j
        character(len=512) :: line
        character(len=24) :: word
        real(dp) :: f(4)
        t%path = path
        open (newunit=u, file=path, status='old', action='read', iostat=ios)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, key//' = '//quoted(path)//': no such file'//ALLOWED)
            return
        end if
        read (u, '(a)', iostat=ios) line
        ok = ios == 0 .and. index(line, '# bifilar identify:') == 1
        if (.not. ok) then
            close (u)
            call set_error(stat, ERR_DECK, key//' = '//quoted(path)//': not an identify '// &
                'output (its first line is not ''# bifilar identify: ...'')'//ALLOWED)
            return
        end if
        ! the budget: the rows after its heading
        allocate (t%rows(0))
        found = .false.
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (.not. found) then
                found = index(line, '# budget of I1') == 1
                cycle
            end if
            if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
            word = line(1:14)
            read (line(15:), *, iostat=ios) f
            if (ios /= 0) then
                close (u)
                call set_error(stat, ERR_DECK, key//' = '//quoted(path)//': a budget row '// &
                    'that is not a name and four numbers: '//quoted(trim(line))//ALLOWED)
                return
            end if
            t%rows = [t%rows, budget_row_t(trim(word), f(1), f(2), f(3), f(4), ROW_INPUT)]
        end do
        close (u)
        do j = 1, size(KEYS)
            call read_kv(path, trim(KEYS(j)), v(j), found)
            if (.not. found) then
                call set_error(stat, ERR_DECK, key//' = '//quoted(path)//': no number '''// &
                    trim(KEYS(j))//''' in it (an older version''s output: run the tare''s '// &
                    'deck again)'//ALLOWED)
                return
            end if
        end do
        t%i1 = v(1)
        t%u_i1 = v(2)
        t%u_own = v(3)
        t%n_own = nint(v(4))
        if (.not. (t%i1 > 0.0_dp) .or. t%u_i1 < 0.0_dp .or. t%u_own < 0.0_dp .or. &
            t%n_own < 0 .or. t%n_own > size(t%rows)) then
            call set_error(stat, ERR_DECK, key//' = '//quoted(path)//': I1 not positive, '// &
                'a negative u or a budget shorter than its own rows'//ALLOWED)
            return
        end if
        call read_kv(path, 'dof_own', x, found)
        t%nu_own = NU_INFINITE
        if (found) t%nu_own = min(NU_INFINITE, max(1.0_dp, x))
        do j = 1, 5
            call read_kv(path, 'rig_'//trim(RIG_KEYS(j)), t%rig(j), found)
            if (found) call read_kv(path, 'u_rig_'//trim(RIG_KEYS(j)), t%u_rig(j), found)
            if (.not. found) then
                call set_error(stat, ERR_DECK, key//' = '//quoted(path)//': no number '// &
                    '''rig_'//trim(RIG_KEYS(j))//''' or its u in it (an older version''s '// &
                    'output: run the tare''s deck again)'//ALLOWED)
                return
            end if
        end do
        call read_kv(path, 'calibration_scale', t%scale, t%calibrated)
        if (t%calibrated) then
            call read_kv(path, 'calibration_delta_l', t%delta_l, found)
        else
            t%scale = 1.0_dp
        end if
    end subroutine read_tare_file

end module tare_file
