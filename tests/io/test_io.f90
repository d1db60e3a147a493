!> Input text handling, the checks' messages, and the HDF5 result file life cycle
!> (temporary name, rename on finish, units attributes, status marks).
program test_io
  use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char, c_null_char, c_f_pointer
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use hdf5, only: hid_t, hsize_t, h5open_f, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F, h5aopen_by_name_f, &
                  h5aget_type_f, h5tis_variable_str_f, h5tget_cset_f, h5aread_f, h5tclose_f, h5aclose_f, &
                  H5T_CSET_UTF8_F
  use h5lt, only: h5ltread_dataset_double_f
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_INVALID_INPUT, STATUS_IO, STATUS_DOMAIN
  use io_input, only: input_text_t, input_from_text, check_positive, check_choice, format_real, &
                      check_known_groups, group_present, group_reader_t, open_group, in_range
  use io_hdf5, only: result_file_t
  use io_system, only: nonregular_kind
  use testing, only: check, check_close_array, finish_tests
  implicit none (type, external)

  call input_text_and_checks()
  call namelist_language()
  call number_formatting()
  call result_file_life_cycle()
  call finish_tests('test_io')

contains

  subroutine input_text_and_checks()
    type(input_text_t) :: input
    type(status_t) :: status
    character(len=1), parameter :: nl = new_line('a')
    call input_from_text('case.nml', '&run'//nl//'/'//nl//'&Surface a=1 /', input, status)
    call check(status%ok() .and. size(input%groups) == 2, 'input text parsed into groups: '//status%text())
    call check(group_present(input, 'surface'), 'group found case-insensitively')
    call check(.not. group_present(input, 'solver'), 'absent group not found')
    call check_known_groups(input, [character(len=8) :: 'run', 'surface'], status)
    call check(status%ok(), 'known groups accepted')
    call check_known_groups(input, [character(len=8) :: 'run'], status)
    call check(status%code == STATUS_INVALID_INPUT .and. index(status%text(), '&surface') > 0 &
               .and. index(status%text(), 'case.nml:3') > 0, 'unknown group named with its line: '//status%text())
    status = status_t()
    call check_positive(input, 'surface', 'a', -2.5_wp, 'm', status)
    call check(index(status%text(), 'case.nml:3: &surface: a = -2.5 is not allowed: must be a finite number > 0 (m)') &
               > 0, 'positive check message: '//status%text())
    status = status_t()
    call check_choice(input, 'surface', 'kind', 'Plane', [character(len=5) :: 'plane', 'torus'], status)
    call check(status%ok(), 'choices compare case-insensitively')
    call check_choice(input, 'surface', 'kind', 'cone', [character(len=5) :: 'plane', 'torus'], status)
    call check(index(status%text(), "kind = 'cone'") > 0 .and. index(status%text(), 'plane torus') > 0, &
               'choice message lists what is allowed: '//status%text())
  end subroutine input_text_and_checks

  !> The lexer: what it reads, and every kind of text it refuses with the line.
  subroutine namelist_language()
    type(input_text_t) :: input
    type(status_t) :: status
    type(group_reader_t) :: r
    character(len=1), parameter :: nl = new_line('a')
    real(wp) :: x, v3(3), parts(4), columns(3, 4)
    real(wp), allocatable :: list(:)
    integer :: i, n_columns
    logical :: flag
    character(len=12) :: word
    character(len=8) :: words(4)

    call input_from_text('t.nml', '! a comment'//nl// &
      '&g  x = 2.5e0, v3 = 3*1.5 ! the rest of the line'//nl// &
      '   list = 1, 2,'//nl//'     3  , 4.0d1'//nl// &
      '   word = ''it''''s'', flag = T'//nl// &
      '   i = -7, parts(3) = 9, words(2:3) = "b", ''c'''//nl// &
      '   columns(:, 2) = 1, 2, 3, columns(2, 4) = 8'//nl//'/'//nl, input, status)
    call check(status%ok(), 'a valid input parses: '//status%text())
    x = 0; v3 = 0; parts = -1; columns = 0; i = 0; flag = .false.; word = ''; words = 'z'
    call open_group(input, 'g', [character(len=8) :: 'x', 'v3', 'list', 'word', 'flag', 'i', 'parts', 'words', &
                    'columns'], r, status)
    call r%get('x', x, in_range(0.0_wp, 10.0_wp, 'm'), status)
    call r%get('v3', v3, in_range(0.0_wp, 10.0_wp, 'm'), status)
    call r%get_list('list', list, 10, in_range(0.0_wp, 100.0_wp, 'm'), status)
    call r%get('word', word, status)
    call r%get('flag', flag, status)
    call r%get('i', i, -10, 10, status)
    call r%get_parts('parts', parts, in_range(0.0_wp, 10.0_wp, '1'), 'n = 4', status)
    call r%get_parts('words', words, 'n = 4', status)
    call r%get_columns('columns', columns, in_range(0.0_wp, 10.0_wp, 'm'), 'n = 4', n_columns, status)
    call check(status%ok(), 'every value read: '//status%text())
    call check(x == 2.5_wp .and. all(v3 == 1.5_wp), 'scalar and repeat count')
    call check(size(list) == 4, 'list over two lines')
    if (size(list) == 4) call check(all(list == [1.0_wp, 2.0_wp, 3.0_wp, 40.0_wp]), 'list values (d exponent)')
    call check(word == 'it''s' .and. flag .and. i == -7, 'doubled quote, logical T, negative integer')
    call check(all(parts == [-1.0_wp, -1.0_wp, 9.0_wp, -1.0_wp]), 'one element given, defaults kept')
    call check(all(words == [character(len=8) :: 'z', 'b', 'c', 'z']), 'a section of texts')
    call check(n_columns == 4 .and. all(columns(:, 2) == [1.0_wp, 2.0_wp, 3.0_wp]) .and. columns(2, 4) == 8, &
               'columns by section and element')

    ! refusals: file, line and what
    call refused('&g x = 1'//nl//'  y = 2'//nl, 't.nml:2:', 'opened at line 1) is not closed', &
                 'a file cut inside a group')
    call refused('&g x = 0.866, 0.0, -', 't.nml:1:', 'cut short', 'a value cut at the end')
    call refused('&g x = 1 /'//nl//'garbage here'//nl, 't.nml:2:', 'text outside a group', 'text between groups')
    call refused('&g x = 1,, 2 /', 't.nml:1:', 'missing', 'a null value')
    call refused('&g x = 3* /', 't.nml:1:', 'null', 'a repeated null value')
    call refused('&g x = /', 't.nml:1:', 'without a value', 'no value')
    call refused('&g x = ''open'//nl//'/', 't.nml:1:', 'not closed', 'an open quote')
    call refused('&g x = 1'//nl//'&h y = 2 /', 't.nml:2:', 'before &h', 'a group inside a group')
    call refused('&g x 1 /', 't.nml:1:', 'expected "="', 'no equals sign')
    call refused('&g x = 1 /'//nl//'Name:'//achar(0)//'x', 't.nml:2:', 'not text', 'a binary file')
    call refused('&g x(1,,2) = 2 /', 't.nml:1:', 'not understood', 'a bad subscript')
    call refused('&g x(1 = 2 /', 't.nml:1:', 'without ")"', 'an open subscript')

    ! refusals of values, by the reader
    call value_refused('x = 1e308', 't.nml:1: &g: x = 1e308 is not allowed: must be a finite number in [0, 10] (m)')
    call value_refused('x = -Inf', 'x = -Inf is not allowed')
    call value_refused('x = NaN', 'x = NaN is not allowed')
    call value_refused('x = 1e400', 'x = 1e400 is not allowed')
    call value_refused('x = 2, 3', 'a single value is expected')
    call value_refused('x = .true.', 'x = .true. is not allowed')
    call value_refused('x = ''two''', "x = 'two' is not allowed")
    call value_refused('i = 2147483648', 'i = 2147483648 is not allowed: must be a whole number in [-10, 10]')
    call value_refused('i = 1e308', 'i = 1e308 is not allowed: must be a whole number')
    call value_refused('i = 2.5', 'i = 2.5 is not allowed')
    call value_refused('v3 = 1, 2', 'needs exactly 3 values, 2 given')
    call value_refused('v3(4) = 1', 'v3(4): the subscript is not allowed: index 4 of v3 lies outside [1, 3]')
    call value_refused('v3(0) = 1', 'index 0 of v3 lies outside [1, 3]')
    call value_refused('v3(2:4) = 1, 2, 3', 'index 4 of v3 lies outside [1, 3]')
    call value_refused('v3(3:2) = 1', 'the section 3:2 of v3 is empty')
    call value_refused('parts(5) = 1', 'index 5 of parts lies outside [1, 4] (n = 4)')
    call value_refused('list = 1, 2, -Inf', 'list(3) = -Inf is not allowed')
    call value_refused('word = ''straight'//repeat('x', 292)//'''', 'is longer than the 12 characters allowed')
    call value_refused('word = straight', 'must be a text in quotes')
    call value_refused('flag = 1', 'flag = 1 is not allowed: must be .true. or .false.')
    call value_refused('e308 = 1', 'unknown variable "e308"')
    call value_refused('x = 1'//nl//'x = 2', 'x is given twice (also at line 1)')
    call value_refused('parts = 1, 2, 3, 4, 5', '5 values are more than n = 4')

    ! a command-line override replaces the text's value and is named in messages
    call input_from_text('t.nml', '&g x = 1, list = 5 /', input, status)
    call input%override('g%x=7', status)
    call input%override('g%list(2)=6', status)
    call check(status%ok(), 'overrides applied: '//status%text())
    x = 0
    call open_group(input, 'g', [character(len=8) :: 'x', 'list'], r, status)
    call r%get('x', x, in_range(0.0_wp, 10.0_wp, 'm'), status)
    call r%get_list('list', list, 10, in_range(0.0_wp, 100.0_wp, 'm'), status)
    call check(status%ok() .and. x == 7, 'override replaces: '//status%text())
    call check(size(list) == 2, 'override adds an element')
    call input%override('g%x=70', status)
    call open_group(input, 'g', [character(len=8) :: 'x', 'list'], r, status)
    call r%get('x', x, in_range(0.0_wp, 10.0_wp, 'm'), status)
    call check(index(status%text(), '--set g%x=70: &g: x = 70 is not allowed') == 1, &
               'an overridden value is refused naming the --set argument: '//status%text())
    status = status_t()
    call input%override('gx=1', status)
    call check(index(status%text(), 'group%variable=value') > 0, 'an override without % refused: '//status%text())
    call check(index(input%text(), '! --set g%x=70') > 0, 'overrides kept with the text')

    ! a group given more than once is changed only where the override says
    ! which: its k-th occurrence or the one of that name; never silently the first
    status = status_t()
    call input_from_text('r.nml', '&g name = ''a'', x = 1 /'//nl//'&g name = ''b'', x = 2 /', input, status)
    call input%override('g%x=5', status)
    call check(status%code == STATUS_INVALID_INPUT .and. index(status%text(), '--set g%x=5: the input has 2 &g') == 1 &
               .and. index(status%text(), '--set "g(2)%x=5"') > 0 .and. index(status%text(), '--set "g(b)%x=5"') > 0, &
               'an override of a repeated group without saying which is refused: '//status%text())
    call check(group_x(input, 1) == 1 .and. group_x(input, 2) == 2, 'a refused override changes nothing')
    status = status_t()
    call input%override('g(2)%x=5', status)
    call check(status%ok() .and. group_x(input, 1) == 1 .and. group_x(input, 2) == 5, &
               'g(2)% changes the second occurrence: '//status%text())
    call input%override('g(a)%x=6', status)
    call input%override('G(''b'')%x=7', status)
    call check(status%ok() .and. group_x(input, 1) == 6 .and. group_x(input, 2) == 7, &
               'g(name)% changes the occurrence of that name: '//status%text())
    call input%override('g(3)%x=1', status)
    call check(index(status%text(), '--set g(3)%x=1: k in g(k) must be 1 to 2') == 1, &
               'an occurrence beyond the last refused: '//status%text())
    status = status_t()
    call input%override('g(c)%x=1', status)
    call check(index(status%text(), 'no &g group has name = ''c''') > 0 .and. index(status%text(), 'g(2) name = ''b''') &
               > 0, 'an unknown name refused, listing the names: '//status%text())
    status = status_t()
    call input%override('h(1)%x=1', status)
    call check(status%ok() .and. group_present(input, 'h'), 'h(1) adds a group not in the input: '//status%text())
    call input%override('k(2)%x=1', status)
    call check(index(status%text(), 'the input has no &k group') > 0, 'k(2) of an absent group refused: '// &
               status%text())
    status = status_t()

    ! on the command line a word is a text without quotes (the shell removes them)
    call input_from_text('t.nml', '&g word = ''x'' /', input, status)
    call input%override('g%word=bdf', status)
    word = ''
    call open_group(input, 'g', [character(len=8) :: 'word'], r, status)
    call r%get('word', word, status, [character(len=5) :: 'adams', 'bdf'])
    call check(status%ok() .and. word == 'bdf', 'an unquoted word from --set is a text: '//status%text())
    call input%override('g%word=bdff', status)
    call open_group(input, 'g', [character(len=8) :: 'word'], r, status)
    call r%get('word', word, status, [character(len=5) :: 'adams', 'bdf'])
    call check(index(status%text(), '--set g%word=bdff: &g: word = bdff is not allowed: must be one of adams bdf') &
               == 1 .and. index(status%text(), 'quotes') == 0, 'a wrong word from --set: '//status%text())
    status = status_t()
    call input%override('g%word=out/x.h5', status)
    call check(index(status%text(), '--set "g%word=''out/x.h5''"') > 0, &
               'a text with / shows the quoting to use: '//status%text())

  end subroutine namelist_language

  !> x of the k-th group g (-1 if not given), as an override left it.
  real(wp) function group_x(input, k) result(x)
    type(input_text_t), intent(in) :: input
    integer, intent(in) :: k
    type(group_reader_t) :: reader
    type(status_t) :: status
    x = -1
    call open_group(input, 'g', [character(len=8) :: 'name', 'x'], reader, status, k)
    call reader%get('x', x, in_range(-10.0_wp, 10.0_wp, 'm'), status)
  end function group_x


  subroutine refused(text, where, what, case)
    character(len=*), intent(in) :: text, where, what, case
    type(input_text_t) :: bad
    type(status_t) :: st
    call input_from_text('t.nml', text, bad, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), where) == 1 .and. &
               index(st%text(), what) > 0, case//': '//st%text())
  end subroutine refused

  subroutine value_refused(assignment, message)
    character(len=*), intent(in) :: assignment, message
    type(input_text_t) :: bad
    type(status_t) :: st
    type(group_reader_t) :: rr
    real(wp) :: xx, vv(3), pp(4)
    real(wp), allocatable :: ll(:)
    integer :: ii
    logical :: ff
    character(len=12) :: ww
    call input_from_text('t.nml', '&g '//assignment//' /', bad, st)
    call open_group(bad, 'g', [character(len=8) :: 'x', 'v3', 'list', 'word', 'flag', 'i', 'parts'], rr, st)
    call rr%get('x', xx, in_range(0.0_wp, 10.0_wp, 'm'), st)
    call rr%get('v3', vv, in_range(0.0_wp, 10.0_wp, 'm'), st)
    call rr%get_list('list', ll, 10, in_range(0.0_wp, 100.0_wp, 'm'), st)
    call rr%get('word', ww, st)
    call rr%get('flag', ff, st)
    call rr%get('i', ii, -10, 10, st)
    call rr%get_parts('parts', pp, in_range(0.0_wp, 10.0_wp, '1'), 'n = 4', st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), message) > 0, &
               assignment(:min(len(assignment), 40))//' refused: '//st%text())
  end subroutine value_refused

  subroutine number_formatting()
    call check(format_real(2.5_wp) == '2.5', 'format 2.5: '//format_real(2.5_wp))
    call check(format_real(-1.0_wp) == '-1.0', 'format -1: '//format_real(-1.0_wp))
    call check(format_real(0.1_wp) == '0.1', 'format 0.1: '//format_real(0.1_wp))
    call check(format_real(1e-10_wp) == '1.0E-10', &
               'format 1e-10: '//format_real(1e-10_wp))
    call check(format_real(123456.75_wp) == '123456.75', 'format 123456.75: '//format_real(123456.75_wp))
  end subroutine number_formatting

  subroutine result_file_life_cycle()
    type(result_file_t) :: file
    type(status_t) :: status
    character(len=*), parameter :: path = 'build_test_io_result.h5'
    integer(hid_t) :: id
    integer :: err
    real(wp) :: back(3, 2), scalar(1)
    logical :: exists
    character(len=:), allocatable :: temporary

    call file%create(path, status)
    call check(status%ok(), 'create: '//status%text())
    temporary = file%temporary_name()
    inquire (file=temporary, exist=exists)
    call check(exists .and. index(temporary, path//'.') == 1 .and. index(temporary, '.tmp') == len(temporary) - 3, &
               'written under a temporary name <path>.<pid>.XXXXXX.tmp while open: '//temporary)
    call file%write_matrix('/group/sub/values', reshape([1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp, 5.0_wp, 6.0_wp], [3, 2]), &
                           'm', 'six numbers', status)
    call file%write_vector('/group/sub/time', [0.0_wp, 0.5_wp], 's', 'two times', status)
    call file%write_scalar('/group/scalar', 2.5_wp, 'N', 'one number', status)
    call file%set_attribute('/group', 'ratio', 0.25_wp, status)
    call file%set_attribute('/group', 'label', 'ä text', status)
    call file%make_scale('/group/sub/time', status)
    call file%attach_scale('/group/sub/time', '/group', status)
    call check(status%ok(), 'writers: '//status%text())
    call file%attach_scale('/group/sub/values', '/group', status)
    call check(index(status%text(), 'not a dimension scale') > 0, 'attach of a non-scale refused: '//status%text())
    status = status_t()
    call file%finish(.false., 'stopped early on purpose', status)
    call check(status%ok(), 'finish: '//status%text())
    inquire (file=temporary, exist=exists)
    call check(.not. exists, 'temporary name gone after finish')
    inquire (file=path, exist=exists)
    call check(exists, 'final name present after finish')

    call h5open_f(err)
    call h5fopen_f(path, H5F_ACC_RDONLY_F, id, err)
    call h5ltread_dataset_double_f(id, '/group/sub/values', back, [3_hsize_t, 2_hsize_t], err)
    call check_close_array(reshape(back, [6]), [1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp, 5.0_wp, 6.0_wp], 0.0_wp, 0.0_wp, &
                           'values read back')
    call h5ltread_dataset_double_f(id, '/group/scalar', scalar, [1_hsize_t], err)
    call check(err == 0 .and. scalar(1) == 2.5_wp, 'scalar read back')
    call check(read_text_attribute(id, '/group/sub/values', 'units') == 'm', 'units attribute')
    call check(read_text_attribute(id, '/', 'status') == 'incomplete', 'status marked incomplete: '// &
               read_text_attribute(id, '/', 'status'))
    call check(read_text_attribute(id, '/group', 'label') == 'ä text', 'UTF-8 text read back')
    call h5fclose_f(id, err)
    open (newunit=err, file=path)
    close (err, status='delete')

    call file%create('no/such/folder/x.h5', status)
    call check(status%code == STATUS_IO .and. index(status%text(), 'no/such/folder/x.h5') > 0, &
               'unwritable path reported: '//status%text())

    ! a NaN written keeps the file from being marked complete and names the dataset
    status = status_t()
    call file%create(path, status)
    call file%write_vector('/a/finite', [1.0_wp, 2.0_wp], 'm', 'finite', status)
    call file%write_vector('/a/not_finite', [1.0_wp, ieee_value(1.0_wp, ieee_quiet_nan)], 'm', 'a NaN', status)
    call check(status%ok(), 'a NaN is written: '//status%text())
    call file%finish(.true., 'ok', status)
    call check(status%code == STATUS_DOMAIN .and. index(status%text(), '/a/not_finite') > 0, &
               'a complete file with a NaN refused, naming the dataset: '//status%text())
    call h5fopen_f(path, H5F_ACC_RDONLY_F, id, err)
    call check(read_text_attribute(id, '/', 'status') == 'incomplete', 'file with a NaN marked incomplete')
    call check(index(read_text_attribute(id, '/', 'status_message'), '/a/not_finite') > 0, &
               'status_message names the dataset')
    call h5fclose_f(id, err)
    open (newunit=err, file=path)
    close (err, status='delete')

    ! a FIFO that appeared at the final name (or its companion's) during the
    ! run is not replaced: exit 3, the results kept in the temporary file(s)
    status = status_t()
    call execute_command_line('rm -f build_test_io_fifo.h5 build_test_io_fifo.xmf', exitstat=err)
    call file%create('build_test_io_fifo.h5', status)
    temporary = file%temporary_name()
    call execute_command_line('mkfifo build_test_io_fifo.h5', exitstat=err)
    call check(err == 0 .and. nonregular_kind('build_test_io_fifo.h5') == 'a FIFO (named pipe)', 'FIFO made')
    call file%write_scalar('/x', 1.0_wp, 'm', 'one number', status)
    call file%finish(.true., 'ok', status)
    inquire (file=temporary, exist=exists)
    call check(status%code == STATUS_IO .and. index(status%text(), 'a FIFO') > 0 .and. &
               index(status%text(), 'kept in "'//temporary//'"') > 0, 'a FIFO at the path refused: '//status%text())
    call check(exists .and. nonregular_kind('build_test_io_fifo.h5') == 'a FIFO (named pipe)', &
               'the FIFO is left alone and the results kept')
    call execute_command_line('rm -f build_test_io_fifo.h5 '//temporary, exitstat=err)

    status = status_t()
    call file%create('build_test_io_fifo.h5', status)
    temporary = file%temporary_name()
    call file%add_companion('build_test_io_fifo.xmf', '<Xdmf/>')
    call execute_command_line('mkfifo build_test_io_fifo.xmf', exitstat=err)
    call file%finish(.true., 'ok', status)
    inquire (file=temporary, exist=exists)
    call check(status%code == STATUS_IO .and. index(status%text(), '"build_test_io_fifo.xmf", where the XDMF') > 0 &
               .and. index(status%text(), 'build_test_io_fifo.xmf.') > 0 .and. exists, &
               'a FIFO at the companion''s path refused, both kept: '//status%text())
    inquire (file='build_test_io_fifo.h5', exist=exists)
    call check(.not. exists .and. nonregular_kind('build_test_io_fifo.xmf') == 'a FIFO (named pipe)', &
               'nothing renamed, the FIFO left alone')
    call execute_command_line('rm -f build_test_io_fifo.xmf build_test_io_fifo.xmf.*.tmp '//temporary, exitstat=err)
  end subroutine result_file_life_cycle

  !> A text attribute, checked to be a scalar variable-length UTF-8 string.
  function read_text_attribute(file_id, object, name) result(text)
    integer(hid_t), intent(in) :: file_id
    character(len=*), intent(in) :: object, name
    character(len=:), allocatable :: text
    integer(hid_t) :: attribute_id, type_id
    type(c_ptr), target :: pointer(1)
    type(c_ptr) :: buffer
    character(kind=c_char), pointer :: chars(:)
    logical :: variable
    integer :: err, cset, n
    text = '(unreadable)'
    call h5aopen_by_name_f(file_id, object, name, attribute_id, err)
    if (err /= 0) return
    call h5aget_type_f(attribute_id, type_id, err)
    call h5tis_variable_str_f(type_id, variable, err)
    call h5tget_cset_f(type_id, cset, err)
    if (variable .and. cset == H5T_CSET_UTF8_F) then
      buffer = c_loc(pointer)
      call h5aread_f(attribute_id, type_id, buffer, err)
      call c_f_pointer(pointer(1), chars, [4096])
      n = 0
      do while (chars(n + 1) /= c_null_char)   ! read up to the terminating NUL only
        n = n + 1
      end do
      text = transfer(chars(:n), repeat(' ', n))
    else
      text = '(not a variable-length UTF-8 string)'
    end if
    call h5tclose_f(type_id, err)
    call h5aclose_f(attribute_id, err)
  end function read_text_attribute
end program test_io
