!> Tables of numbers as instruments and spreadsheets write them: a text file of rows, read
!! and checked whole (read_table).
!!
!! * Separators: blanks or tabs, a comma, or a semicolon between fields, found from the
!!   file's first data line (a semicolon wins over a comma; with semicolons, a comma inside
!!   a number is its decimal point, as in 0,012;1,35).  Quoted fields ("Time (s)") keep
!!   their separators; the quotes are dropped.
!! * Line ends LF or CR LF; a UTF-8 byte order mark at the start is skipped; '#' starts a
!!   comment; blank lines are skipped.
!! * Header: the lines before the first line whose fields are all numbers.  The last header
!!   line with as many fields as the data names the columns (names compared in lower case,
!!   trimmed); a table without such a line has no names.
!! * Data: every data line has the same number of fields, each a finite number (a field of
!!   more than 64 characters, NaN, Inf or a value beyond the range of real(dp) is refused);
!!   a line longer than LINE_MAX characters is refused.
!! * Text columns (read_table's text_columns, e.g. a table of releases naming a record
!!   file): the first line is then the header and must name every column; the fields of
!!   the columns named there are kept as text (tab%text), the others must be numbers.
!! * The file: a regular file (a FIFO, a device or a folder is refused before it is
!!   opened: module file_kind), of at most MAX_TABLE_BYTES, read once whole into memory;
!!   its bytes can go back to the caller (a record's CRC-64 in NAME.identify).
!! * Some columns only (read_picked, a record): the file's text (load_table_file) with the
!!   columns asked for, by number or by their name in the header (matched in lower case,
!!   trimmed; a name without its unit matches a column whose name adds one, as 'gyroscope
!!   z' matches 'Gyroscope z (rad/s)', when only one does); only those must be numbers, the
!!   other columns may hold anything, text included.  The data start at the first line
!!   whose asked columns are numbers (after the header that names them, when asked by
!!   name); every data line has as many fields as the first.
!! * A column's name: its unit is the text of its last parentheses or brackets ('Time (s)':
!!   's'; name_unit), its base what stands before them ('time'; name_base).
!! Failures are ERR_DECK statuses whose message names the line and what is wrong; the
!! caller puts the file's name before it.
module tables
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, lower, clip, quoted
    use, intrinsic :: iso_fortran_env, only: int64
    use lines, only: LINE_MAX
    use file_kind, only: kind_of_file, kind_name, FILE_REGULAR, FILE_MISSING
    use fptraps, only: traps_off, traps_restore, NTRAPS
    implicit none
    private

    !> One column's name.
    type, public :: column_name_t
        character(len=:), allocatable :: s
    end type column_name_t

    !> A table read from a file.
    type, public :: table_t
        integer :: nrow = 0, ncol = 0
        real(dp), allocatable :: v(:, :)            !! (nrow, ncol) the values
        integer, allocatable :: line(:)             !! (nrow) each row's line in the file
        type(column_name_t), allocatable :: names(:)    !! (ncol) lower case; '' when none
        !> (nrow, ncol) the fields of the text columns ('' in the others), with text_columns
        type(column_name_t), allocatable :: text(:, :)
        character :: separator = ' '                !! ' ', ',' or ';'
        logical :: decimal_comma = .false.          !! ';' separated with a comma for a point
        !> (read_picked) the file's column of each column of v, in the order asked
        integer, allocatable :: pick(:)
        integer :: header_line = 0                  !! the line that named the columns (0: none)
    contains
        procedure :: column => table_column
    end type table_t

    public :: read_table, load_table_file, read_picked, header_fields, name_unit, name_base

    integer, parameter :: FIELD_MAX = 64        !! longest numeric field (characters)
    !> Largest table file (bytes): 512 MiB, room for 2 000 000 samples of long numbers
    integer(int64), parameter, public :: MAX_TABLE_BYTES = 536870912_int64

contains

    !> Read the table at path (max_rows rows at most; 0: no limit): the file read once,
    !! whole, into memory (load_file), then taken apart line by line.  bytes: the file's
    !! bytes as read (for a checksum), when asked.
    subroutine read_table(path, tab, stat, max_rows, text_columns, bytes)
        character(len=*), intent(in) :: path        !! the file
        type(table_t), intent(out) :: tab
        type(status_t), intent(out) :: stat         !! ERR_DECK naming the line
        integer, intent(in), optional :: max_rows   !! most data rows (0 or absent: no limit)
        !> names (lower case) of the columns whose fields are text; the header is required
        character(len=*), intent(in), optional :: text_columns(:)
        !> the file's bytes, as read
        character(len=:), allocatable, intent(out), optional :: bytes
        character(len=:), allocatable :: text, why
        type(column_name_t), allocatable :: f(:), header(:)
        real(dp), allocatable :: v(:, :), x(:)
        integer, allocatable :: ln(:)
        logical, allocatable :: is_text(:)
        type(column_name_t), allocatable :: txt(:, :)
        integer :: ios, nline, n, nmax, k
        integer(int64) :: pos
        logical :: halting(NTRAPS), numeric, with_text
        stat%code = STATUS_OK
        nmax = 0
        if (present(max_rows)) nmax = max_rows
        call load_file(path, text, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. allocated(text)) text = ''
        allocate (header(0), v(1, 1024), ln(1024), is_text(0))
        with_text = present(text_columns)
        n = 0
        nline = 0
        pos = 1
        call traps_off(halting)
        do
            call next_fields(text, pos, nline, n == 0, tab, f, ios)
            if (ios < 0) exit
            if (ios > 0) then
                call fail(too_long(nline))
                return
            end if
            if (with_text) then
                if (size(header) == 0) then
                    ! the header: it names the columns, and which hold text
                    call to_numbers(f, tab%decimal_comma, x, numeric)
                    if (numeric) then
                        call fail('line '//itoa(nline)//' is numbers; allowed: a first '// &
                                  'line (header) naming the columns')
                        return
                    end if
                    header = f
                    allocate (txt(size(f), 1024))
                    is_text = [(any(lower(trim(adjustl(f(k)%s))) == text_columns), &
                                k=1, size(f))]
                    cycle
                end if
                if (size(f) /= size(header)) then
                    call fail('line '//itoa(nline)//': '//itoa(size(f))//' fields where '// &
                              'the header names '//itoa(size(header))//'; allowed: one '// &
                              'field per column on every line')
                    return
                end if
                call keep_text(f, n + 1)
                where (is_text) f = zero_field()
            end if
            call to_numbers(f, tab%decimal_comma, x, numeric)
            if (.not. numeric .and. n == 0 .and. .not. with_text .and. size(header) == size(f)) then
                ! after the header, a line of numbers with an empty field is a data row
                ! with a cell left empty, not a second header
                if (empty_cell(f) > 0) then
                    call fail('line '//itoa(nline)//': field '//itoa(empty_cell(f))//' ('// &
                              clip(trim(adjustl(header(empty_cell(f))%s)))//') is empty; '// &
                              'allowed: a number in every field after the header')
                    return
                end if
            end if
            if (.not. numeric) then
                if (n > 0 .or. with_text) then
                    call fail('line '//itoa(nline)//': '//non_number(f, tab%decimal_comma)// &
                              '; allowed: numbers in every field after the header')
                    return
                end if
                header = f
                cycle
            end if
            if (n == 0) then
                tab%ncol = size(x)
                deallocate (v)
                allocate (v(tab%ncol, 1024))
            else if (size(x) /= tab%ncol) then
                call fail('line '//itoa(nline)//': '//itoa(size(x))//' fields where the '// &
                          'first data line has '//itoa(tab%ncol)//'; allowed: the same '// &
                          'number of fields on every line')
                return
            end if
            call keep_row(x, nline, nmax, v, ln, n, why)
            if (len(why) > 0) then
                call fail(why)
                return
            end if
        end do
        call traps_restore(halting)
        if (present(bytes)) call move_alloc(text, bytes)
        tab%nrow = n
        if (n == 0) then
            call set_error(stat, ERR_DECK, 'no line of numbers (a header alone, or empty); '// &
                           'allowed: rows of numbers, after an optional header')
            return
        end if
        tab%v = transpose(v(:, 1:n))
        tab%line = ln(1:n)
        if (with_text) tab%text = transpose(txt(:, 1:n))
        call set_names(tab, header)
    contains
        subroutine fail(what)
            character(len=*), intent(in) :: what
            call traps_restore(halting)
            call set_error(stat, ERR_DECK, what)
        end subroutine fail
        !> The text columns' fields of data row i (the others '').
        subroutine keep_text(ff, i)
            type(column_name_t), intent(in) :: ff(:)
            integer, intent(in) :: i
            integer :: j
            if (i > size(txt, 2)) txt = reshape(txt, [size(txt, 1), 2*size(txt, 2)], &
                                                pad=txt(:, 1:1))
            do j = 1, size(ff)
                txt(j, i)%s = ''
                if (is_text(j)) txt(j, i)%s = ff(j)%s
            end do
        end subroutine keep_text
        !> A field that reads as 0 (a text column's place among the numbers).
        !> The first empty field of a line whose other fields are all numbers (0: none).
        integer function empty_cell(ff)
            type(column_name_t), intent(in) :: ff(:)
            real(dp) :: xx
            integer :: j
            empty_cell = 0
            do j = 1, size(ff)
                if (len_trim(ff(j)%s) == 0) then
                    if (empty_cell == 0) empty_cell = j
                else if (.not. number(ff(j)%s, tab%decimal_comma, xx)) then
                    empty_cell = 0
                    return
                end if
            end do
        end function empty_cell
        elemental function zero_field() result(z)
            type(column_name_t) :: z
            z%s = '0'
        end function zero_field
    end subroutine read_table

    !> The whole file at path as text (load_file: a regular file, at most MAX_TABLE_BYTES,
    !! read once), for read_picked and header_fields; its bytes are what a checksum takes.
    subroutine load_table_file(path, text, stat)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        type(status_t), intent(out) :: stat         !! ERR_DECK
        stat%code = STATUS_OK
        call load_file(path, text, stat)
        if (.not. allocated(text)) text = ''
    end subroutine load_table_file

    !> The columns asked for of a table's text (load_table_file): tab%v(:, k) the column
    !! pick_at(k) (1-based) or, where pick_at(k) = 0, the column named pick_names(k) (lower
    !! case) in the header; tab%pick(k) its place in the file.  Only the columns asked for
    !! must be numbers (finite); the others may hold anything.  The header: the line that
    !! names every column asked by name, else the last line before the data with as many
    !! fields as the data (tab%names, tab%header_line).  At most max_rows data rows (0: no
    !! limit).  who: the key that asks for the columns, for messages.
    subroutine read_picked(text, tab, stat, max_rows, pick_at, pick_names, who)
        character(len=*), intent(in) :: text        !! the file's text
        type(table_t), intent(out) :: tab
        type(status_t), intent(out) :: stat         !! ERR_DECK naming the line
        integer, intent(in) :: max_rows             !! most data rows (0: no limit)
        integer, intent(in) :: pick_at(:)           !! columns (1-based; 0: by name)
        character(len=*), intent(in) :: pick_names(:)   !! names (lower case) where pick_at = 0
        character(len=*), intent(in) :: who         !! e.g. 'record_columns'
        character(len=:), allocatable :: why
        type(column_name_t), allocatable :: f(:), header(:), first_text(:)
        real(dp), allocatable :: v(:, :), x(:), xa(:)
        integer, allocatable :: ln(:), idx(:)
        integer :: ios, nline, n, np, hline
        integer(int64) :: pos
        logical :: halting(NTRAPS), resolved, numeric, all_numeric
        stat%code = STATUS_OK
        np = size(pick_at)
        idx = pick_at
        resolved = all(idx > 0)
        hline = 0
        allocate (header(0), first_text(0), v(max(1, np), 1024), ln(1024))
        n = 0
        nline = 0
        pos = 1
        call traps_off(halting)
        do
            call next_fields(text, pos, nline, n == 0, tab, f, ios)
            if (ios < 0) exit
            if (ios > 0) then
                call fail(too_long(nline))
                return
            end if
            if (.not. resolved) then
                ! the header that names the columns asked by name, before any data
                call to_numbers(f, tab%decimal_comma, xa, all_numeric)
                if (all_numeric) then
                    call fail('line '//itoa(nline)//' holds numbers, and no line before it '// &
                              'names the column '//quoted(clip(first_unnamed()))// &
                              trim(named_in(first_text))//'; allowed: '//who// &
                              ' naming columns of the header, or their numbers (1, 2, ...)')
                    return
                end if
                call resolve(f)
                if (stat%code /= STATUS_OK) return
                if (.not. resolved .and. size(first_text) == 0) first_text = f
                if (resolved) then
                    header = f
                    hline = nline
                end if
                cycle
            end if
            call picked_numbers(f, x, numeric)
            if (n == 0) then
                if (.not. numeric) then
                    if (maxval(idx) > size(f)) then
                        call to_numbers(f, tab%decimal_comma, xa, all_numeric)
                        if (all_numeric) then
                            call fail(itoa(size(f))//' columns (line '//itoa(nline)//'), '// &
                                who//' asks for column '//itoa(maxval(idx))//'; allowed: '// &
                                who//' naming columns of the file (1 .. '//itoa(size(f))//')')
                            return
                        end if
                    end if
                    ! a line before the data: the header when no column is asked by name
                    if (all(pick_at > 0)) then
                        header = f
                        hline = nline
                    end if
                    cycle
                end if
                tab%ncol = size(f)
                if (any(pick_at == 0) .and. size(header) /= tab%ncol) then
                    call fail('the header (line '//itoa(hline)//') names '// &
                              itoa(size(header))//' columns, the first line of numbers (line '// &
                              itoa(nline)//') has '//itoa(tab%ncol)//' fields; allowed: one '// &
                              'name per column (quote names that hold the separator)')
                    return
                end if
                deallocate (v)
                allocate (v(max(1, np), 1024))
            else if (size(f) /= tab%ncol) then
                call fail('line '//itoa(nline)//': '//itoa(size(f))//' fields where the '// &
                          'first data line has '//itoa(tab%ncol)//'; allowed: the same '// &
                          'number of fields on every line')
                return
            else if (.not. numeric) then
                call fail('line '//itoa(nline)//': '//picked_non_number(f)//'; allowed: '// &
                          'numbers in the columns '//who//' asks for')
                return
            end if
            call keep_row(x, nline, max_rows, v, ln, n, why)
            if (len(why) > 0) then
                call fail(why)
                return
            end if
        end do
        call traps_restore(halting)
        if (.not. resolved) then
            call set_error(stat, ERR_DECK, 'no line names the column '// &
                           quoted(clip(first_unnamed()))//trim(named_in(first_text))// &
                           '; allowed: '//who//' naming columns of the header, or their '// &
                           'numbers (1, 2, ...)')
            return
        end if
        tab%nrow = n
        if (n == 0) then
            call set_error(stat, ERR_DECK, 'no line of numbers in the columns '//who// &
                           ' asks for (a header alone, or empty); allowed: rows of numbers, '// &
                           'after an optional header')
            return
        end if
        tab%v = transpose(v(1:np, 1:n))
        tab%line = ln(1:n)
        tab%pick = idx
        call set_names(tab, header)
        if (size(header) == tab%ncol) tab%header_line = hline
    contains
        subroutine fail(what)
            character(len=*), intent(in) :: what
            call traps_restore(halting)
            call set_error(stat, ERR_DECK, what)
        end subroutine fail
        !> The columns asked by name found among the fields ff (resolved when all are).
        subroutine resolve(ff)
            type(column_name_t), intent(in) :: ff(:)
            integer :: kk, at
            idx = pick_at
            do kk = 1, np
                if (pick_at(kk) > 0) cycle
                at = find_named(ff, pick_names(kk))
                if (at < 0) then
                    call fail('line '//itoa(nline)//' names the column '// &
                              quoted(clip(trim(pick_names(kk))))//' more than once; '// &
                              'allowed: '//who//' naming a column the header names once '// &
                              '(or its number)')
                    return
                end if
                idx(kk) = at
            end do
            resolved = all(idx > 0)
            if (.not. resolved) idx = pick_at
        end subroutine resolve
        !> The first name asked for that the header does not name ('' when none).
        function first_unnamed() result(s)
            character(len=:), allocatable :: s
            integer :: kk
            s = ''
            do kk = 1, np
                if (pick_at(kk) > 0) cycle
                if (size(first_text) > 0) then
                    if (find_named(first_text, pick_names(kk)) > 0) cycle
                end if
                s = trim(pick_names(kk))
                return
            end do
        end function first_unnamed
        !> The fields of the columns asked for as numbers; numeric false when a column is
        !! missing or one is not a number.
        subroutine picked_numbers(ff, xx, ok)
            type(column_name_t), intent(in) :: ff(:)
            real(dp), allocatable, intent(out) :: xx(:)
            logical, intent(out) :: ok
            integer :: kk
            allocate (xx(np))
            xx = 0.0_dp
            ok = maxval(idx) <= size(ff)
            if (.not. ok) return
            do kk = 1, np
                ok = number(ff(idx(kk))%s, tab%decimal_comma, xx(kk))
                if (.not. ok) return
            end do
        end subroutine picked_numbers
        !> The first column asked for whose field is not a number, quoted for a message.
        function picked_non_number(ff) result(s)
            type(column_name_t), intent(in) :: ff(:)
            character(len=:), allocatable :: s
            real(dp) :: xx
            integer :: kk
            s = 'a field asked for is not a number'
            do kk = 1, np
                if (.not. number(ff(idx(kk))%s, tab%decimal_comma, xx)) then
                    s = 'field '//itoa(idx(kk))//', '''//clip(ff(idx(kk))%s)//''', is not a number'
                    return
                end if
            end do
        end function picked_non_number
    end subroutine read_picked

    !> '; the header names: 'a', 'b', ...' (the first names, clipped), '' for no fields.
    function named_in(ff) result(s)
        type(column_name_t), intent(in) :: ff(:)
        character(len=:), allocatable :: s
        integer :: k
        s = ''
        if (size(ff) == 0) return
        s = '; the header names '
        do k = 1, min(size(ff), 12)
            if (k > 1) s = s//', '
            s = s//quoted(clip(lower(trim(adjustl(ff(k)%s)))))
        end do
        if (size(ff) > 12) s = s//', ...'
    end function named_in

    !> The field of ff named `name` (lower case): its exact name, else, when only one field
    !! has it, the name without its unit ('gyroscope z' for 'Gyroscope z (rad/s)'); 0 when
    !! none, -1 when two fields have the name.
    function find_named(ff, name) result(at)
        type(column_name_t), intent(in) :: ff(:)
        character(len=*), intent(in) :: name
        integer :: at
        integer :: k, nexact, nbase, kb
        character(len=:), allocatable :: nm
        nm = lower(trim(adjustl(name)))
        at = 0
        nexact = 0
        nbase = 0
        kb = 0
        if (len(nm) == 0) return
        do k = 1, size(ff)
            if (lower(trim(adjustl(ff(k)%s))) == nm) then
                nexact = nexact + 1
                at = k
            else if (name_base(ff(k)%s) == nm) then
                nbase = nbase + 1
                kb = k
            end if
        end do
        if (nexact > 1) at = -1
        if (nexact == 0 .and. nbase == 1) at = kb
        if (nexact == 0 .and. nbase > 1) at = -1
    end function find_named

    !> The fields of the first line of a table's text that holds anything ('#' comments and
    !! blank lines skipped), lower case and trimmed; named: that line is not all numbers (a
    !! header).  Lines of more than LINE_MAX characters are left to the reader.
    subroutine header_fields(text, f, named)
        character(len=*), intent(in) :: text
        type(column_name_t), allocatable, intent(out) :: f(:)
        logical, intent(out) :: named
        type(table_t) :: tab
        real(dp), allocatable :: x(:)
        integer(int64) :: pos
        integer :: ios, nline, k
        logical :: halting(NTRAPS)
        named = .false.
        pos = 1
        nline = 0
        call traps_off(halting)
        call next_fields(text, pos, nline, .true., tab, f, ios)
        if (ios == 0) then
            call to_numbers(f, tab%decimal_comma, x, named)
            named = .not. named
            do k = 1, size(f)
                f(k)%s = lower(trim(adjustl(f(k)%s)))
            end do
        else
            allocate (f(0))
        end if
        call traps_restore(halting)
    end subroutine header_fields

    !> The fields of the next line of text from pos that holds anything ('#' comments and
    !! blank lines skipped, a byte order mark dropped from line 1; nline counts the lines),
    !! the separator chosen on that line when choose.  state: 0 fields read, -1 the text's
    !! end, 1 line nline is longer than LINE_MAX (too_long).
    subroutine next_fields(text, pos, nline, choose, tab, f, state)
        character(len=*), intent(in) :: text
        integer(int64), intent(inout) :: pos
        integer, intent(inout) :: nline
        logical, intent(in) :: choose
        type(table_t), intent(inout) :: tab
        type(column_name_t), allocatable, intent(out) :: f(:)
        integer, intent(out) :: state
        character(len=:), allocatable :: line
        integer :: ios
        do
            call next_line(text, pos, line, ios)
            state = -1
            if (ios < 0) return
            nline = nline + 1
            state = 1
            if (len(line) > LINE_MAX) return
            if (nline == 1) call drop_bom(line)
            call drop_comment(line)
            if (len_trim(line) == 0) cycle
            if (choose) call choose_separator(line, tab)
            call split_fields(line, tab%separator, f)
            state = 0
            return
        end do
    end subroutine next_fields

    !> The message of a line longer than LINE_MAX.
    pure function too_long(nline) result(why)
        integer, intent(in) :: nline
        character(len=:), allocatable :: why
        why = 'line '//itoa(nline)//' is longer than '//itoa(LINE_MAX)//' characters; '// &
              'allowed: lines of at most '//itoa(LINE_MAX)
    end function too_long

    !> Row x of line nline kept as column n + 1 of v (v and its lines ln doubled when
    !! full): why '' then, else what is wrong (a value not finite; more than nmax rows,
    !! when nmax > 0).
    subroutine keep_row(x, nline, nmax, v, ln, n, why)
        real(dp), intent(in) :: x(:)
        integer, intent(in) :: nline, nmax
        real(dp), allocatable, intent(inout) :: v(:, :)
        integer, allocatable, intent(inout) :: ln(:)
        integer, intent(inout) :: n
        character(len=:), allocatable, intent(out) :: why
        why = ''
        if (.not. all(ieee_is_finite(x))) then
            why = 'line '//itoa(nline)//': a value is not a finite number (NaN, Inf, or '// &
                  'beyond 1.8e308); allowed: finite numbers'
        else if (nmax > 0 .and. n == nmax) then
            why = 'more than '//itoa(nmax)//' rows; allowed: at most '//itoa(nmax)
        else
            if (n == size(v, 2)) then
                v = reshape(v, [size(v, 1), 2*n], pad=[0.0_dp])
                ln = [ln, ln]
            end if
            n = n + 1
            v(1:size(x), n) = x
            ln(n) = nline
        end if
    end subroutine keep_row

    !> tab%names: the header's fields, lower case and trimmed ('' each when the header
    !! has not tab%ncol of them).
    subroutine set_names(tab, header)
        type(table_t), intent(inout) :: tab
        type(column_name_t), intent(in) :: header(:)
        integer :: k
        allocate (tab%names(tab%ncol))
        do k = 1, tab%ncol
            tab%names(k)%s = ''
            if (size(header) == tab%ncol) tab%names(k)%s = lower(trim(adjustl(header(k)%s)))
        end do
    end subroutine set_names

    !> A column name's unit: the text inside its last parentheses or brackets, lower case,
    !! blanks dropped ('Gyroscope z (rad/s)': 'rad/s'); '' when it has none.
    pure function name_unit(name) result(u)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: u
        integer :: i1, i2, k
        character(len=:), allocatable :: s
        s = trim(name)
        u = ''
        call unit_span(s, i1, i2)
        if (i1 == 0) return
        do k = i1 + 1, i2 - 1
            if (s(k:k) /= ' ') u = u//s(k:k)
        end do
        u = lower(u)
    end function name_unit

    !> A column name without its unit, lower case and trimmed ('Time (s)': 'time').
    pure function name_base(name) result(b)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: b
        integer :: i1, i2
        character(len=:), allocatable :: s
        s = trim(adjustl(name))
        call unit_span(s, i1, i2)
        if (i1 > 0) s = s(1:i1 - 1)//s(i2 + 1:)
        b = lower(trim(adjustl(s)))
    end function name_base

    !> Where the unit of a name stands: s(i1:i2) its last '(...)' or '[...]' (i1 = 0: none).
    pure subroutine unit_span(s, i1, i2)
        character(len=*), intent(in) :: s
        integer, intent(out) :: i1, i2
        integer :: j1, j2
        i1 = 0
        i2 = 0
        j2 = index(s, ')', back=.true.)
        if (j2 > 0) then
            j1 = index(s(1:j2), '(', back=.true.)
            if (j1 > 0) then
                i1 = j1
                i2 = j2
            end if
        end if
        j2 = index(s, ']', back=.true.)
        if (j2 > i2) then
            j1 = index(s(1:j2), '[', back=.true.)
            if (j1 > 0) then
                i1 = j1
                i2 = j2
            end if
        end if
    end subroutine unit_span

    !> The whole file at path, read once (a stream of bytes) after its kind is known
    !! (module file_kind: a FIFO, a device or a folder is refused before it is opened, so
    !! nothing blocks or reads for ever); at most MAX_TABLE_BYTES; a file whose size changed
    !! while it was read (a logger still writing) is refused.
    subroutine load_file(path, text, stat)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        type(status_t), intent(inout) :: stat       !! ERR_DECK
        character(len=512) :: msg
        integer :: u, ios, k
        integer(int64) :: size0, size1
        k = kind_of_file(path)
        if (k /= FILE_REGULAR .and. k /= FILE_MISSING) then
            call set_error(stat, ERR_DECK, 'is '//trim(kind_name(k))//', not a file of '// &
                           'text (reading it could wait or go on for ever); allowed: a '// &
                           'regular text file')
            return
        end if
        msg = ''
        open (newunit=u, file=path, status='old', action='read', access='stream', &
              form='unformatted', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, 'cannot open it: '//trim(msg)//'; allowed: a '// &
                           'readable text file')
            return
        end if
        inquire (unit=u, size=size0)
        if (size0 > MAX_TABLE_BYTES) then
            close (u)
            call set_error(stat, ERR_DECK, 'it has '//itoa64(size0)//' bytes; allowed: at '// &
                           'most '//itoa64(MAX_TABLE_BYTES)//' bytes')
            return
        end if
        allocate (character(len=max(0_int64, size0)) :: text)
        ios = 0
        if (size0 > 0) read (u, iostat=ios, iomsg=msg) text
        inquire (unit=u, size=size1)
        close (u)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, 'cannot read it: '//trim(msg)//'; allowed: a '// &
                           'readable text file')
        else if (size1 /= size0) then
            call set_error(stat, ERR_DECK, 'its size changed while it was read ('// &
                           itoa64(size0)//' bytes, then '//itoa64(size1)//'): is it still '// &
                           'being written?; allowed: a finished file')
        end if
    end subroutine load_file

    !> The next line of text from byte pos on (pos moves past its line end), tabs and
    !! carriage returns as blanks; ios = -1 at the end of the text.
    pure subroutine next_line(text, pos, line, ios)
        character(len=*), intent(in) :: text
        integer(int64), intent(inout) :: pos
        character(len=:), allocatable, intent(out) :: line
        integer, intent(out) :: ios
        integer(int64) :: j, n
        integer :: i
        ios = 0
        n = len(text, kind=int64)
        if (pos > n) then
            ios = -1
            line = ''
            return
        end if
        j = index(text(pos:), achar(10), kind=int64)
        if (j == 0) then
            line = text(pos:)
            pos = n + 1
        else
            line = text(pos:pos + j - 2)
            pos = pos + j
        end if
        do i = 1, len(line)
            if (line(i:i) == achar(9) .or. line(i:i) == achar(13)) line(i:i) = ' '
        end do
    end subroutine next_line

    !> A 64-bit integer without blanks.
    pure function itoa64(i) result(s)
        integer(int64), intent(in) :: i
        character(len=len_trim(i64_text(i))) :: s
        s = i64_text(i)
    end function itoa64

    pure function i64_text(i) result(s)
        integer(int64), intent(in) :: i
        character(len=24) :: s
        write (s, '(i0)') i
    end function i64_text

    !> The column named `name` (lower case), 0 when the table has none of that name.
    pure integer function table_column(tab, name) result(k)
        class(table_t), intent(in) :: tab
        character(len=*), intent(in) :: name
        integer :: j
        k = 0
        if (.not. allocated(tab%names)) return
        do j = 1, size(tab%names)
            if (tab%names(j)%s == lower(trim(adjustl(name)))) then
                k = j
                return
            end if
        end do
    end function table_column

    !> A UTF-8 byte order mark (EF BB BF) at the start of the first line is dropped.
    subroutine drop_bom(line)
        character(len=:), allocatable, intent(inout) :: line
        if (len(line) < 3) return
        if (iachar(line(1:1)) == 239 .and. iachar(line(2:2)) == 187 .and. &
            iachar(line(3:3)) == 191) line = line(4:)
    end subroutine drop_bom

    !> Everything from a '#' outside quotes on is a comment.
    subroutine drop_comment(line)
        character(len=:), allocatable, intent(inout) :: line
        integer :: i
        logical :: q
        q = .false.
        do i = 1, len(line)
            if (line(i:i) == '"') q = .not. q
            if (line(i:i) == '#' .and. .not. q) then
                line = line(1:i - 1)
                return
            end if
        end do
    end subroutine drop_comment

    !> The separator of a table from its first non-blank line: ';' when it holds one
    !! outside quotes, else ',' when it holds one, else blanks (and tabs); with ';', a comma
    !! in the data is a decimal comma.
    subroutine choose_separator(line, tab)
        character(len=*), intent(in) :: line
        type(table_t), intent(inout) :: tab
        integer :: i
        logical :: q, semi, comma
        q = .false.
        semi = .false.
        comma = .false.
        do i = 1, len(line)
            if (line(i:i) == '"') q = .not. q
            if (q) cycle
            if (line(i:i) == ';') semi = .true.
            if (line(i:i) == ',') comma = .true.
        end do
        tab%separator = ' '
        if (comma) tab%separator = ','
        if (semi) tab%separator = ';'
        tab%decimal_comma = semi
    end subroutine choose_separator

    !> The fields of a line: separated by sep (blanks: any run of blanks), quotes dropped,
    !! each field trimmed.  With a comma or semicolon an empty field counts.
    subroutine split_fields(line, sep, f)
        character(len=*), intent(in) :: line
        character, intent(in) :: sep
        type(column_name_t), allocatable, intent(out) :: f(:)
        character(len=len(line)) :: buf
        integer :: i, nb, nf
        logical :: q, in_field
        allocate (f(0))
        buf = ''
        nb = 0
        q = .false.
        in_field = .false.
        nf = 0
        do i = 1, len(line)
            if (line(i:i) == '"') then
                q = .not. q
                in_field = .true.
                cycle
            end if
            if (.not. q .and. ((sep == ' ' .and. line(i:i) == ' ') .or. &
                               (sep /= ' ' .and. line(i:i) == sep))) then
                if (sep /= ' ' .or. in_field) call push()
                cycle
            end if
            if (line(i:i) /= ' ' .or. in_field) then
                nb = nb + 1
                buf(nb:nb) = line(i:i)
                in_field = .true.
            end if
        end do
        if (in_field .or. (sep /= ' ' .and. nf > 0)) call push()
    contains
        subroutine push()
            type(column_name_t) :: one
            one%s = trim(buf(1:nb))
            f = [f, one]
            nf = nf + 1
            buf = ''
            nb = 0
            in_field = .false.
        end subroutine push
    end subroutine split_fields

    !> The fields as numbers; numeric is .false. when one is not a number (then x is empty).
    subroutine to_numbers(f, decimal_comma, x, numeric)
        type(column_name_t), intent(in) :: f(:)
        logical, intent(in) :: decimal_comma
        real(dp), allocatable, intent(out) :: x(:)
        logical, intent(out) :: numeric
        integer :: k
        allocate (x(size(f)))
        numeric = size(f) > 0
        do k = 1, size(f)
            numeric = number(f(k)%s, decimal_comma, x(k))
            if (.not. numeric) exit
        end do
        if (.not. numeric) deallocate (x)
        if (.not. numeric) allocate (x(0))
    end subroutine to_numbers

    !> The first field that is not a number, quoted for a message.
    function non_number(f, decimal_comma) result(s)
        type(column_name_t), intent(in) :: f(:)
        logical, intent(in) :: decimal_comma
        character(len=:), allocatable :: s
        real(dp) :: x
        integer :: k
        s = 'a field is not a number'
        do k = 1, size(f)
            if (.not. number(f(k)%s, decimal_comma, x)) then
                s = 'field '//itoa(k)//', '''//clip(f(k)%s)//''', is not a number'
                return
            end if
        end do
    end function non_number

    !> A field as a number: digits, sign, point (or decimal comma), exponent; an empty or
    !! longer than FIELD_MAX field is none.
    logical function number(s, decimal_comma, x)
        character(len=*), intent(in) :: s
        logical, intent(in) :: decimal_comma
        real(dp), intent(out) :: x
        character(len=len(s)) :: t
        integer :: ios, i
        x = 0.0_dp
        number = .false.
        t = adjustl(s)
        if (len_trim(t) == 0 .or. len_trim(t) > FIELD_MAX) return
        if (decimal_comma) then
            do i = 1, len_trim(t)
                if (t(i:i) == ',') t(i:i) = '.'
            end do
        end if
        if (verify(trim(t), '0123456789+-.eEdD') /= 0) then
            ! NaN and Inf are numbers to the reader: refused later as not finite
            if (lower(trim(t)) /= 'nan' .and. lower(trim(t)) /= 'inf' .and. &
                lower(trim(t)) /= '-inf' .and. lower(trim(t)) /= '+inf') return
        end if
        if (scan(trim(t), '0123456789') == 0 .and. lower(trim(t)) /= 'nan' .and. &
            index(lower(t), 'inf') == 0) return
        read (t, *, iostat=ios) x
        number = ios == 0
    end function number

end module tables
