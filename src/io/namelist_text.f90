!> The text of a namelist file and the explanation of a namelist read error, for any file
!! of namelist groups (the deck): the group names that start somewhere, each group's text
!! found as the run-time library finds it, what the run-time library cannot be trusted with
!! (an open subscript, an overlong value), and, when its read fails, the first item whose
!! name is unknown, whose value has the wrong form or which has too many values (its own
!! small tokenizer).
!!
!! A group's variables are described by a spec: blank-separated 'name:KN' words, K the kind
!! (r real, i integer, c character, l logical, k a column: an integer or a quoted name) and
!! N the number of elements, e.g. 'b:r1 inertia:r3 title:c1'.
module namelist_text
    use status, only: status_t, set_error, ERR_DECK
    use text, only: itoa, lower, next_word, commas, clip, is_ident
    implicit none
    private

    !> One line of a file in memory (tabs and carriage returns as blanks).
    type, public :: text_line_t
        character(len=:), allocatable :: s
    end type text_line_t

    !> Longest value of a group (characters, quoted or not): a title or a word holds 256.
    integer, parameter, public :: MAX_TEXT = 256

    public :: check_group_names, scan_group, long_text, subscript_problem, explain, with_allowed

contains

    !> Every '&name' that starts a group (outside comments) must be a known group; '&end'
    !! closes a group.  `seen` lists the groups that start somewhere (' name name ... ',
    !! lower case).
    subroutine check_group_names(lines, allowed, stat, seen)
        type(text_line_t), intent(in) :: lines(:)   !! the file's lines
        character(len=*), intent(in) :: allowed     !! the group names allowed, blank-separated
        type(status_t), intent(inout) :: stat       !! ERR_DECK on an unknown group
        character(len=:), allocatable, intent(out) :: seen   !! ' name name ... '
        character(len=:), allocatable :: line, word
        integer :: i, j, k
        seen = ' '
        do k = 1, size(lines)
            line = lines(k)%s
            i = index(line, '!')
            if (i > 0) line = line(1:i - 1)
            do i = 1, len(line) - 1
                if (line(i:i) /= '&') cycle
                if (i > 1) then
                    if (line(i - 1:i - 1) /= ' ' .and. line(i - 1:i - 1) /= '/') cycle
                end if
                j = i + 1
                do while (j <= len(line))
                    if (.not. is_ident(line(j:j))) exit
                    j = j + 1
                end do
                if (j == i + 1) cycle
                word = lower(line(i + 1:j - 1))
                if (word == 'end') cycle
                if (index(' '//allowed//' ', ' '//word//' ') == 0) then
                    call set_error(stat, ERR_DECK, 'unknown namelist group &'// &
                                   clip(line(i + 1:j - 1))//'; allowed: &'// &
                                   commas(allowed, ', &'))
                    return
                end if
                if (index(seen, ' '//word//' ') == 0) seen = seen//word//' '
            end do
        end do
    end subroutine check_group_names

    !> Find the first '&grp' outside comments and collect its text up to the closing '/' or
    !! '&end' (outside quotes), comments removed, lines joined by blanks (`text`, for the
    !! diagnosis; `breaks` lists the positions in text where a line ended), and the group
    !! as one record for the namelist reader (`rec`: '&grp', the items, ' /'; a line that
    !! ends inside a quoted value is joined without a blank, as the run-time library reads
    !! a value continued on the next record).  Linear in the deck's size.
    subroutine scan_group(lines, grp, found, complete, text, breaks, rec)
        type(text_line_t), intent(in) :: lines(:)   !! the file's lines
        character(len=*), intent(in) :: grp         !! group name, lower case
        logical, intent(out) :: found               !! a line starts the group
        logical, intent(out) :: complete            !! the group is closed
        character(len=:), allocatable, intent(out) :: text   !! its items, for the diagnosis
        character(len=:), allocatable, intent(out) :: rec    !! the group as one record
        integer, allocatable, intent(out) :: breaks(:)       !! where lines ended in text
        character(len=:), allocatable :: buf, rbuf
        integer, allocatable :: brk(:)
        character :: q
        integer :: i, n, i0, nt, nr, nb, k
        found = .false.
        complete = .false.
        q = ' '
        nt = 0
        nr = 0
        nb = 0
        allocate (character(len=256) :: buf, rbuf)
        allocate (brk(16))
        call append_rec('&'//grp//' ')
        do k = 1, size(lines)
            associate (line => lines(k)%s)
            i = 1
            if (.not. found) then
                ! look for &grp, as the run-time library does (no quotes outside a group)
                n = len(grp)
                do i = 1, len(line)
                    if (q == ' ' .and. line(i:i) == '!') exit
                    if (line(i:i) /= '&' .or. i + n > len(line)) cycle
                    if (lower(line(i + 1:i + n)) /= grp) cycle
                    if (i + n < len(line)) then
                        if (is_ident(line(i + n + 1:i + n + 1))) cycle
                    end if
                    found = .true.
                    exit
                end do
                if (.not. found) cycle
                i = i + n + 1
            end if
            i0 = i
            do while (i <= len(line))
                if (q /= ' ') then
                    if (line(i:i) == q) q = ' '
                else if (line(i:i) == '!') then
                    exit
                else if (line(i:i) == '''' .or. line(i:i) == '"') then
                    q = line(i:i)
                else if (line(i:i) == '/') then
                    complete = .true.
                    exit
                else if (line(i:i) == '&' .and. i + 3 <= len(line)) then
                    if (lower(line(i:i + 3)) == '&end') then
                        complete = .true.
                        if (i + 4 <= len(line)) complete = .not. is_ident(line(i + 4:i + 4))
                        if (complete) exit
                    end if
                end if
                i = i + 1
            end do
            call append(line(i0:i - 1)//' ')
            if (q /= ' ') then
                call append_rec(line(i0:i - 1))
            else
                call append_rec(line(i0:i - 1)//' ')
            end if
            end associate
            if (complete) exit
            nb = nb + 1
            if (nb > size(brk)) brk = [brk, brk]
            brk(nb) = nt
        end do
        text = buf(1:nt)
        breaks = brk(1:nb)
        call append_rec('/')
        rec = rbuf(1:nr)

    contains

        !> Append s to buf(1:nt), doubling its length when full.
        subroutine append(s)
            character(len=*), intent(in) :: s
            character(len=:), allocatable :: grown
            if (nt + len(s) > len(buf)) then
                allocate (character(len=2*(nt + len(s))) :: grown)
                grown(1:nt) = buf(1:nt)
                call move_alloc(grown, buf)
            end if
            buf(nt + 1:nt + len(s)) = s
            nt = nt + len(s)
        end subroutine append

        !> Append s to rbuf(1:nr), doubling its length when full.
        subroutine append_rec(s)
            character(len=*), intent(in) :: s
            character(len=:), allocatable :: grown
            if (nr + len(s) > len(rbuf)) then
                allocate (character(len=2*(nr + len(s))) :: grown)
                grown(1:nr) = rbuf(1:nr)
                call move_alloc(grown, rbuf)
            end if
            rbuf(nr + 1:nr + len(s)) = s
            nr = nr + len(s)
        end subroutine append_rec

    end subroutine scan_group

    !> A value longer than MAX_TEXT characters, quoted or not ('' when none): the run-time
    !! library would cut it to its variable's length (and the checking build prints a
    !! warning); no number needs as many digits.
    function long_text(text) result(why)
        character(len=*), intent(in) :: text        !! a group's items (scan_group)
        character(len=:), allocatable :: why
        character :: q
        integer :: k, k0, n
        why = ''
        q = ' '
        n = 0
        k0 = 1
        do k = 1, len(text)
            if (q == ' ') then
                if (text(k:k) == '''' .or. text(k:k) == '"') then
                    q = text(k:k)
                    n = 0
                    k0 = k
                    cycle
                else if (index(' ,=', text(k:k)) > 0) then
                    n = 0
                    k0 = k + 1
                    cycle
                end if
            else if (text(k:k) == q) then
                q = ' '      ! a doubled quote closes and reopens: counted as two values
                n = 0
                cycle
            end if
            n = n + 1
            if (n > MAX_TEXT) then
                why = 'a value of more than '//itoa(MAX_TEXT)//' characters ('// &
                    clip(text(k0:))//'); allowed: at most '//itoa(MAX_TEXT)
                return
            end if
        end do
    end function long_text

    !> The first parenthesis of a group's text that the run-time library cannot be trusted
    !! with (gfortran 12 takes SIGSEGV on a subscript left open at the end of a line): every
    !! '(' outside quotes must follow a variable name, close on the same line, and hold only
    !! digits, blanks, '+', '-', ':' and ','.  Empty when all are well formed.
    function subscript_problem(text, breaks) result(why)
        character(len=*), intent(in) :: text        !! a group's items (scan_group)
        integer, intent(in) :: breaks(:)            !! where its lines ended
        character(len=:), allocatable :: why
        character :: q
        integer :: k, j, b, e, nextb
        why = ''
        q = ' '
        b = 1
        k = 0
        do while (k < len(text))
            k = k + 1
            if (q /= ' ') then
                if (text(k:k) == q) q = ' '
                cycle
            end if
            if (text(k:k) == '''' .or. text(k:k) == '"') then
                q = text(k:k)
                cycle
            end if
            if (text(k:k) == ')') then
                why = 'unexpected '')'' in '''//clip(item_at(k))//''''
                return
            end if
            if (text(k:k) /= '(') cycle
            ! the variable name before '('
            j = k - 1
            do while (j >= 1)
                if (text(j:j) /= ' ') exit
                j = j - 1
            end do
            if (j < 1) then
                why = 'unexpected ''('' in '''//clip(item_at(k))//'''; subscripts follow a '// &
                      'variable name, e.g. inertia(1) = 0.1'
                return
            end if
            if (.not. is_ident(text(j:j))) then
                why = 'unexpected ''('' in '''//clip(item_at(k))//'''; subscripts follow a '// &
                      'variable name, e.g. inertia(1) = 0.1, and values have no parentheses'
                return
            end if
            do while (b <= size(breaks))
                if (breaks(b) >= k) exit
                b = b + 1
            end do
            nextb = len(text)
            if (b <= size(breaks)) nextb = breaks(b)
            e = index(text(k + 1:nextb), ')')
            if (e == 0) then
                why = 'subscript '''//clip(item_at(k))//''' not closed on its line; '// &
                      'allowed: a subscript on one line, e.g. btilde(1,:) = 1, 0, 0'
                return
            end if
            e = k + e
            do while (j > 1)
                if (.not. is_ident(text(j - 1:j - 1))) exit
                j = j - 1
            end do
            if (verify(text(k + 1:e - 1), '0123456789+-:, ') /= 0 .or. &
                len_trim(text(k + 1:e - 1)) == 0) then
                why = 'bad subscript '''//clip(text(j:e))//'''; allowed: integers, '':'' '// &
                      'and '','', e.g. inertia(2) or btilde(1,:)'
                return
            end if
            k = e
        end do

    contains

        !> The line of text that holds position p.
        function item_at(p) result(s)
            integer, intent(in) :: p
            character(len=:), allocatable :: s
            integer :: i1, i2, bb
            i1 = 1
            i2 = len(text)
            do bb = 1, size(breaks)
                if (breaks(bb) >= p) then
                    i2 = breaks(bb)
                    exit
                end if
                i1 = breaks(bb) + 1
            end do
            s = trim(adjustl(text(i1:i2)))
        end function item_at

    end function subscript_problem

    !> Explain why the run-time library could not read a group: the first item whose name is
    !! unknown, whose value has the wrong form, or which has too many values.  Empty when no
    !! explanation is found.
    function explain(text, grp, spec) result(why)
        character(len=*), intent(in) :: text        !! a group's items (scan_group)
        character(len=*), intent(in) :: grp         !! its name
        character(len=*), intent(in) :: spec        !! its variables (see the module header)
        character(len=:), allocatable :: why
        integer :: neq, k, j, depth, p1, v1, v2, t1, t2, nval, cnt, star, ios
        integer, allocatable :: eqs(:), nstart(:), nend(:)
        logical :: subscripted
        character :: q, kind
        character(len=:), allocatable :: nm, tok, val, names, lhs
        integer :: vsize

        why = ''
        val = ''
        lhs = ''
        allocate (eqs(count([(text(k:k) == '=', k = 1, len(text))])))
        neq = 0
        q = ' '
        do k = 1, len(text)
            if (q /= ' ') then
                if (text(k:k) == q) q = ' '
            else if (text(k:k) == '''' .or. text(k:k) == '"') then
                q = text(k:k)
            else if (text(k:k) == '=') then
                neq = neq + 1
                eqs(neq) = k
            end if
        end do
        names = spec_names(spec)
        q = ' '
        do k = 1, len(text) - 1
            if (q /= ' ') then
                if (text(k:k) == q) q = ' '
            else if (text(k:k) == '''' .or. text(k:k) == '"') then
                q = text(k:k)
            else if (text(k:k) == '&' .and. is_ident(text(k + 1:k + 1))) then
                j = k + 1
                do while (j <= len(text))
                    if (.not. is_ident(text(j:j))) exit
                    j = j + 1
                end do
                why = 'no closing ''/'' before '''//clip(text(k:j - 1))//''''
                return
            end if
        end do
        if (neq == 0) then
            if (len_trim(text) > 0) why = 'expected name = value, found '''// &
                clip(trim(adjustl(text)))//'''; allowed variables: '//names
            return
        end if
        allocate (nstart(neq), nend(neq))
        do k = 1, neq
            j = eqs(k) - 1
            do while (j >= 1)
                if (text(j:j) /= ' ') exit
                j = j - 1
            end do
            if (j >= 1) then
                if (text(j:j) == ')') then
                    depth = 0
                    do while (j >= 1)
                        if (text(j:j) == ')') depth = depth + 1
                        if (text(j:j) == '(') depth = depth - 1
                        if (depth == 0) exit
                        j = j - 1
                    end do
                    j = j - 1
                    do while (j >= 1)
                        if (text(j:j) /= ' ') exit
                        j = j - 1
                    end do
                end if
            end if
            nend(k) = j
            do while (j >= 1)
                if (.not. is_ident(text(j:j))) exit
                j = j - 1
            end do
            nstart(k) = j + 1
            if (nstart(k) > nend(k)) then
                why = 'expected a variable name before ''='' in '''//clip(trim(adjustl(text)))// &
                    '''; allowed variables: '//names
                return
            end if
        end do
        if (len_trim(text(1:nstart(1) - 1)) > 0) then
            why = 'unexpected '''//clip(trim(adjustl(text(1:nstart(1) - 1))))// &
                ''' before the first variable'
            return
        end if
        do k = 1, neq
            nm = lower(text(nstart(k):nend(k)))
            subscripted = eqs(k) > nend(k) + 1
            if (subscripted) subscripted = len_trim(text(nend(k) + 1:eqs(k) - 1)) > 0
            lhs = clip(trim(text(nstart(k):eqs(k) - 1)))
            call spec_lookup(spec, nm, kind, vsize)
            if (kind == ' ') then
                why = 'unknown variable '''//clip(text(nstart(k):nend(k)))//''' in &'//grp// &
                    '; allowed variables: '//names
                return
            end if
            v1 = eqs(k) + 1
            v2 = len(text)
            if (k < neq) v2 = nstart(k + 1) - 1
            val = trim(adjustl(text(v1:v2)))
            if (len(val) > 0) then
                if (val(len(val):len(val)) == ',') val = trim(val(1:len(val) - 1))
            end if
            val = clip(val)
            ! tokens separated by blanks or commas outside quotes
            nval = 0
            p1 = v1
            do
                call next_token(text(1:v2), p1, t1, t2)
                if (t1 == 0) exit
                p1 = t2 + 1
                tok = text(t1:t2)
                cnt = 1
                star = index(tok, '*')
                if (star > 1 .and. tok(1:1) /= '''' .and. tok(1:1) /= '"') then
                    read (tok(1:star - 1), '(i20)', iostat=ios) cnt
                    if (ios /= 0 .or. verify(tok(1:star - 1), '0123456789') /= 0) then
                        cnt = 1
                    else
                        tok = tok(star + 1:)
                    end if
                end if
                nval = nval + cnt
                if (len(tok) == 0) cycle
                if (.not. token_ok(tok, kind)) then
                    select case (kind)
                    case ('r')
                        why = lhs//' = '//val//': '''//clip(tok)// &
                            ''' is not a real number'
                    case ('i')
                        why = lhs//' = '//val//': '''//clip(tok)// &
                            ''' is not an integer'
                    case ('c')
                        why = lhs//' = '//val//': character values '// &
                            'must be quoted, e.g. '//nm//' = ''...'''
                    case ('k')
                        why = lhs//' = '//val//': '''//clip(tok)// &
                            ''' is neither a whole number nor a quoted name'
                    case default
                        why = lhs//' = '//val//': '''//clip(tok)// &
                            ''' is not a logical; allowed: .true., .false.'
                    end select
                    return
                end if
            end do
            if (.not. subscripted .and. nval > vsize) then
                why = lhs//' = '//val//': too many values for '//nm// &
                    ' (it holds '//itoa(vsize)//')'
                return
            end if
        end do
    end function explain

    !> Next token of s after position p (blanks and commas separate; quotes kept whole).
    subroutine next_token(s, p, t1, t2)
        character(len=*), intent(in) :: s           !! text
        integer, intent(in) :: p                    !! start searching here
        integer, intent(out) :: t1, t2              !! token s(t1:t2); t1 = 0 when none
        integer :: i
        character :: q
        t1 = 0
        t2 = 0
        i = p
        do while (i <= len(s))
            if (s(i:i) /= ' ' .and. s(i:i) /= ',') exit
            i = i + 1
        end do
        if (i > len(s)) return
        t1 = i
        q = ' '
        do while (i <= len(s))
            if (q /= ' ') then
                if (s(i:i) == q) q = ' '
            else if (s(i:i) == '''' .or. s(i:i) == '"') then
                q = s(i:i)
            else if (s(i:i) == ' ' .or. s(i:i) == ',') then
                exit
            end if
            i = i + 1
        end do
        t2 = i - 1
    end subroutine next_token

    !> Whether a value token has the form its kind needs.
    logical function token_ok(tok, kind)
        character(len=*), intent(in) :: tok         !! the token (repeat count removed)
        character, intent(in) :: kind               !! r, i, c or l
        character(len=:), allocatable :: s
        s = lower(tok)
        select case (kind)
        case ('r')
            token_ok = is_real(s)
        case ('i')
            if (s(1:1) == '+' .or. s(1:1) == '-') s = s(2:)
            token_ok = len(s) > 0
            if (token_ok) token_ok = verify(s, '0123456789') == 0
        case ('c')
            token_ok = .false.
            if (len(s) >= 2) token_ok = (s(1:1) == '''' .or. s(1:1) == '"') .and. &
                s(len(s):len(s)) == s(1:1)
        case ('k')
            ! a quoted name, or a whole number
            token_ok = .false.
            if (len(s) >= 2) token_ok = (s(1:1) == '''' .or. s(1:1) == '"') .and. &
                s(len(s):len(s)) == s(1:1)
            if (.not. token_ok) then
                if (s(1:1) == '+' .or. s(1:1) == '-') s = s(2:)
                token_ok = len(s) > 0
                if (token_ok) token_ok = verify(s, '0123456789') == 0
            end if
        case default
            if (s(1:1) == '.') s = s(2:)
            token_ok = .false.
            if (len(s) > 0) token_ok = s(1:1) == 't' .or. s(1:1) == 'f'
        end select
    end function token_ok

    !> Whether s (lower case) is a Fortran real literal, NaN or Inf.
    logical function is_real(s)
        character(len=*), intent(in) :: s           !! candidate, lower case
        integer :: i, nd
        is_real = .false.
        i = 1
        if (len(s) == 0) return
        if (s(1:1) == '+' .or. s(1:1) == '-') i = 2
        if (i > len(s)) return
        if (s(i:) == 'nan' .or. s(i:) == 'inf' .or. s(i:) == 'infinity') then
            is_real = .true.
            return
        end if
        nd = 0
        do while (i <= len(s))
            if (index('0123456789', s(i:i)) == 0) exit
            nd = nd + 1
            i = i + 1
        end do
        if (i <= len(s)) then
            if (s(i:i) == '.') then
                i = i + 1
                do while (i <= len(s))
                    if (index('0123456789', s(i:i)) == 0) exit
                    nd = nd + 1
                    i = i + 1
                end do
            end if
        end if
        if (nd == 0) return
        if (i > len(s)) then
            is_real = .true.
            return
        end if
        if (index('edq', s(i:i)) > 0) i = i + 1
        if (i <= len(s)) then
            if (s(i:i) == '+' .or. s(i:i) == '-') i = i + 1
        end if
        if (i > len(s)) return
        is_real = verify(s(i:), '0123456789') == 0
    end function is_real

    function with_allowed(what, note, spec) result(m)
        character(len=*), intent(in) :: what        !! the problem ('...; allowed: ...' or not)
        character(len=*), intent(in) :: note        !! put before the allowed part
        character(len=*), intent(in) :: spec        !! the group's variables
        character(len=:), allocatable :: m
        integer :: i
        i = index(what, '; allowed')
        if (i > 0) then
            m = what(1:i - 1)//note//what(i:)
        else
            m = what//note//'; allowed: name = value items of the group''s variables ('// &
                spec_names(spec)//'), values of their kind, closed by ''/'''
        end if
    end function with_allowed

    !> Blank-separated names of a spec, as 'a, b, c'.
    function spec_names(spec) result(s)
        character(len=*), intent(in) :: spec        !! see SPEC_*
        character(len=:), allocatable :: s
        integer :: i1, i2, c
        s = ''
        i2 = 0
        do
            call next_word(spec, i2, i1)
            if (i1 == 0) exit
            c = index(spec(i1:i2), ':')
            if (len(s) > 0) s = s//', '
            s = s//spec(i1:i1 + c - 2)
        end do
    end function spec_names

    !> Kind and size of variable nm in spec; kind = ' ' when unknown.
    subroutine spec_lookup(spec, nm, kind, vsize)
        character(len=*), intent(in) :: spec        !! see SPEC_*
        character(len=*), intent(in) :: nm          !! variable name, lower case
        character, intent(out) :: kind              !! r, i, c, l or blank
        integer, intent(out) :: vsize               !! number of elements
        integer :: i1, i2, c, ios
        kind = ' '
        vsize = 0
        i2 = 0
        do
            call next_word(spec, i2, i1)
            if (i1 == 0) exit
            c = i1 + index(spec(i1:i2), ':') - 1
            if (spec(i1:c - 1) == nm) then
                kind = spec(c + 1:c + 1)
                read (spec(c + 2:i2), *, iostat=ios) vsize
                return
            end if
        end do
    end subroutine spec_lookup

end module namelist_text
