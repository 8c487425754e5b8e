!> The certificate of a measurement: one self-contained HTML page that prints on A4, the
!! document an engineer attaches to a test report (GUM clause 7: every source of uncertainty
!! documented).  The page needs no other file and runs no script: its style is inline and
!! its figures are inline SVG (module svg_plot).
!!
!! An analysis fills a `certificate_t` section by section (`cert_section`), each with a
!! paragraph, tables (`cert_table`, `cert_row`: cells separated by CELL, a tab) and
!! figures (`cert_figure`), and writes it with `cert_write` into the run's files.  The page
!! ends with the program's version, the deck's CRC-64 and the date and time of the run.
!! Every text is escaped for HTML.  No routine stops.
module certificate
    use status, only: status_t
    use output_io, only: out_files_t
    use svg_plot, only: html_escaped => xml_escaped   ! &, <, > and " escaped
    implicit none
    private

    !> The separator of a table row's cells in cert_row's text.
    character(len=1), parameter, public :: CELL = achar(9)

    type :: cert_part_t
        integer :: kind = 0                     !! PART_* below
        character(len=:), allocatable :: text   !! a paragraph, a row, a caption, an <svg>
    end type cert_part_t

    !> A certificate being filled.
    type, public :: certificate_t
        character(len=:), allocatable :: title, subtitle
        character(len=:), allocatable :: version, deck_crc, deck_path
        type(cert_part_t), allocatable :: parts(:)
    end type certificate_t

    integer, parameter :: PART_SECTION = 1, PART_TEXT = 2, PART_TABLE = 3, PART_HEAD = 4, &
                          PART_ROW = 5, PART_FIGURE = 6, PART_NOTE = 7

    public :: cert_new, cert_section, cert_text, cert_table, cert_row, cert_figure, cert_html
    public :: cert_write, html_escaped, cert_note, cert_now

contains

    !> A certificate with its title and what identifies the run.
    pure function cert_new(title, subtitle, version, deck_path, deck_crc) result(c)
        character(len=*), intent(in) :: title, subtitle, version, deck_path, deck_crc
        type(certificate_t) :: c
        c%title = title
        c%subtitle = subtitle
        c%version = version
        c%deck_path = deck_path
        c%deck_crc = deck_crc
        allocate (c%parts(0))
    end function cert_new

    pure subroutine add(c, kind, text)
        type(certificate_t), intent(inout) :: c
        integer, intent(in) :: kind
        character(len=*), intent(in) :: text
        type(cert_part_t), allocatable :: grown(:)
        integer :: k
        allocate (grown(size(c%parts) + 1))
        do k = 1, size(c%parts)
            call move_alloc(c%parts(k)%text, grown(k)%text)
            grown(k)%kind = c%parts(k)%kind
        end do
        grown(size(grown))%kind = kind
        grown(size(grown))%text = text
        call move_alloc(grown, c%parts)
    end subroutine add

    !> A new numbered section.
    pure subroutine cert_section(c, heading)
        type(certificate_t), intent(inout) :: c
        character(len=*), intent(in) :: heading
        call add(c, PART_SECTION, heading)
    end subroutine cert_section

    !> A paragraph.
    pure subroutine cert_text(c, text)
        type(certificate_t), intent(inout) :: c
        character(len=*), intent(in) :: text
        call add(c, PART_TEXT, text)
    end subroutine cert_text

    !> A highlighted note (a warning that stands, a check that failed).
    pure subroutine cert_note(c, text)
        type(certificate_t), intent(inout) :: c
        character(len=*), intent(in) :: text
        call add(c, PART_NOTE, text)
    end subroutine cert_note

    !> A new table with its header cells (separated by CELL).
    pure subroutine cert_table(c, header)
        type(certificate_t), intent(inout) :: c
        character(len=*), intent(in) :: header
        call add(c, PART_TABLE, '')
        call add(c, PART_HEAD, header)
    end subroutine cert_table

    !> A row of the last table (cells separated by CELL).
    pure subroutine cert_row(c, cells)
        type(certificate_t), intent(inout) :: c
        character(len=*), intent(in) :: cells
        call add(c, PART_ROW, cells)
    end subroutine cert_row

    !> A figure (an <svg> element) with its caption.
    pure subroutine cert_figure(c, svg, caption)
        type(certificate_t), intent(inout) :: c
        character(len=*), intent(in) :: svg, caption
        call add(c, PART_FIGURE, svg)
        call add(c, PART_TEXT, caption)
        c%parts(size(c%parts))%kind = -PART_FIGURE     ! the caption of the figure before
    end subroutine cert_figure

    !> The page.  `stamp` is the date and time of the run as text.
    function cert_html(c, stamp) result(s)
        type(certificate_t), intent(in) :: c
        character(len=*), intent(in) :: stamp
        character(len=:), allocatable :: s
        integer :: k, nsec
        logical :: in_table
        s = '<!DOCTYPE html>'//achar(10)//'<html lang="en"><head><meta charset="utf-8">'// &
            '<title>'//html_escaped(c%title)//'</title>'//achar(10)//'<style>'// &
            '@page { size: A4; margin: 16mm 14mm; } '// &
            'body { font-family: Helvetica, Arial, sans-serif; font-size: 10pt; color: #111; '// &
            'max-width: 182mm; margin: 0 auto; } '// &
            'h1 { font-size: 16pt; margin: 0 0 2pt 0; } '// &
            'h2 { font-size: 12pt; border-bottom: 1px solid #888; margin: 14pt 0 4pt 0; '// &
            'page-break-after: avoid; } '// &
            'p.sub { color: #444; margin: 0 0 8pt 0; } '// &
            'table { border-collapse: collapse; margin: 4pt 0 8pt 0; page-break-inside: avoid; } '// &
            'th, td { border: 1px solid #bbb; padding: 2pt 5pt; text-align: left; '// &
            'vertical-align: top; } '// &
            'th { background: #eee; } td.n { text-align: right; font-variant-numeric: '// &
            'tabular-nums; } '// &
            'figure { margin: 6pt 0; page-break-inside: avoid; } '// &
            'figure svg { max-width: 100%; height: auto; } '// &
            'figcaption { font-size: 9pt; color: #333; } '// &
            'p.note { border-left: 3pt solid #c60; padding-left: 6pt; } '// &
            'footer { margin-top: 16pt; font-size: 8.5pt; color: #444; border-top: 1px solid '// &
            '#888; padding-top: 4pt; }'// &
            '</style></head>'//achar(10)//'<body>'//achar(10)
        s = s//'<h1>'//html_escaped(c%title)//'</h1>'//achar(10)//'<p class="sub">'// &
            html_escaped(c%subtitle)//'</p>'//achar(10)
        in_table = .false.
        nsec = 0
        do k = 1, size(c%parts)
            if (in_table .and. c%parts(k)%kind /= PART_HEAD .and. &
                c%parts(k)%kind /= PART_ROW) then
                s = s//'</table>'//achar(10)
                in_table = .false.
            end if
            select case (c%parts(k)%kind)
            case (PART_SECTION)
                nsec = nsec + 1
                s = s//'<h2>'//itoa_local(nsec)//'. '//html_escaped(c%parts(k)%text)//'</h2>'// &
                    achar(10)
            case (PART_TEXT)
                s = s//'<p>'//html_escaped(c%parts(k)%text)//'</p>'//achar(10)
            case (PART_NOTE)
                s = s//'<p class="note">'//html_escaped(c%parts(k)%text)//'</p>'//achar(10)
            case (PART_TABLE)
                s = s//'<table>'
                in_table = .true.
            case (PART_HEAD)
                s = s//'<tr>'//cells(c%parts(k)%text, 'th')//'</tr>'//achar(10)
            case (PART_ROW)
                s = s//'<tr>'//cells(c%parts(k)%text, 'td')//'</tr>'//achar(10)
            case (PART_FIGURE)
                s = s//'<figure>'//c%parts(k)%text
                if (k < size(c%parts)) then
                    if (c%parts(k + 1)%kind == -PART_FIGURE) s = s//'<figcaption>'// &
                        html_escaped(c%parts(k + 1)%text)//'</figcaption>'
                end if
                s = s//'</figure>'//achar(10)
            end select
        end do
        if (in_table) s = s//'</table>'//achar(10)
        s = s//'<footer>bifilar '//html_escaped(c%version)//' &middot; deck '// &
            html_escaped(c%deck_path)//' &middot; CRC-64 of the deck '// &
            html_escaped(c%deck_crc)//' &middot; '//html_escaped(stamp)//'</footer>'// &
            achar(10)//'</body></html>'//achar(10)
    end function cert_html

    !> The cells of a row: text cells as given, cells that read as a number right-aligned.
    pure function cells(text, tag) result(s)
        character(len=*), intent(in) :: text, tag
        character(len=:), allocatable :: s
        integer :: i0, i
        character(len=:), allocatable :: cl
        s = ''
        i0 = 1
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= CELL) cycle
            end if
            cl = text(i0:i - 1)
            if (tag == 'td' .and. numeric(cl)) then
                s = s//'<td class="n">'//html_escaped(cl)//'</td>'
            else
                s = s//'<'//tag//'>'//html_escaped(cl)//'</'//tag//'>'
            end if
            i0 = i + 1
        end do
    end function cells

    !> A cell that reads as a number (digits, sign, point, exponent, ±).
    pure logical function numeric(t)
        character(len=*), intent(in) :: t
        integer :: i
        numeric = len_trim(t) > 0
        do i = 1, len_trim(t)
            if (index('0123456789+-.Ee %', t(i:i)) == 0) numeric = .false.
        end do
    end function numeric

    pure function itoa_local(n) result(s)
        integer, intent(in) :: n
        character(len=:), allocatable :: s
        character(len=12) :: buf
        write (buf, '(i0)') n
        s = trim(buf)
    end function itoa_local

    !> The date and time now, ISO 8601 with the offset from UTC: a page's stamp.
    function cert_now() result(s)
        character(len=:), allocatable :: s
        character(len=8) :: dd
        character(len=10) :: tt
        character(len=5) :: zz
        call date_and_time(dd, tt, zz)
        s = dd(1:4)//'-'//dd(5:6)//'-'//dd(7:8)//' '//tt(1:2)//':'//tt(3:4)//':'//tt(5:6)// &
            ' '//zz(1:3)//':'//zz(4:5)
    end function cert_now

    !> Write the page as `path` into the run's files (it appears with them, whole or not at
    !! all); `stamp` is the run's date and time.
    subroutine cert_write(c, path, stamp, files, stat)
        type(certificate_t), intent(in) :: c
        character(len=*), intent(in) :: path, stamp
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        integer :: u, ios, i, i0
        character(len=:), allocatable :: page
        call files%open(path, u, stat)
        if (stat%code /= 0) return
        page = cert_html(c, stamp)
        ios = 0
        i0 = 1
        do i = 1, len(page)
            if (page(i:i) /= achar(10)) cycle
            if (ios == 0) write (u, '(a)', iostat=ios) page(i0:i - 1)
            i0 = i + 1
        end do
        if (i0 <= len(page) .and. ios == 0) write (u, '(a)', iostat=ios) page(i0:)
        call files%close(u, ios, stat)
    end subroutine cert_write

end module certificate
