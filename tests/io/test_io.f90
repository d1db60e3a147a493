!> Input text handling, the checks' messages, and the HDF5 result file life cycle
!> (temporary name, rename on finish, units attributes, status marks).
program test_io
  use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char, c_null_char, c_f_pointer
  use hdf5, only: hid_t, hsize_t, h5open_f, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F, h5aopen_by_name_f, &
                  h5aget_type_f, h5tis_variable_str_f, h5tget_cset_f, h5aread_f, h5tclose_f, h5aclose_f, &
                  H5T_CSET_UTF8_F
  use h5lt, only: h5ltread_dataset_double_f
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use io_input, only: input_text_t, input_from_text, check_positive, check_choice, format_real, &
                      check_known_groups, group_present
  use io_hdf5, only: result_file_t
  use testing, only: check, check_close_array, finish_tests
  implicit none (type, external)

  call input_text_and_checks()
  call number_formatting()
  call result_file_life_cycle()
  call finish_tests('test_io')

contains

  subroutine input_text_and_checks()
    type(input_text_t) :: input
    type(status_t) :: status
    call input_from_text('case.nml', '&run'//new_line('a')//'/'//new_line('a')//'&Surface a=1 /', input)
    call check(size(input%lines) == 3, 'input text split into lines')
    call check(group_present(input, 'surface'), 'group found case-insensitively')
    call check(.not. group_present(input, 'solver'), 'absent group not found')
    call check_known_groups(input, [character(len=8) :: 'run', 'surface'], status)
    call check(status%ok(), 'known groups accepted')
    call check_known_groups(input, [character(len=8) :: 'run'], status)
    call check(status%code == STATUS_INVALID_INPUT .and. index(status%text(), '&surface') > 0 &
               .and. index(status%text(), 'case.nml') > 0, 'unknown group named: '//status%text())
    status = status_t()
    call check_positive(input, 'surface', 'a', -2.5_wp, 'm', status)
    call check(index(status%text(), 'case.nml: &surface: a = -2.5 is not allowed: must be a finite number > 0 (m)') > 0, &
               'positive check message: '//status%text())
    status = status_t()
    call check_choice(input, 'surface', 'kind', 'Plane', [character(len=5) :: 'plane', 'torus'], status)
    call check(status%ok(), 'choices compare case-insensitively')
    call check_choice(input, 'surface', 'kind', 'cone', [character(len=5) :: 'plane', 'torus'], status)
    call check(index(status%text(), "kind = 'cone'") > 0 .and. index(status%text(), 'plane torus') > 0, &
               'choice message lists what is allowed: '//status%text())
  end subroutine input_text_and_checks

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

    call file%create(path, status)
    call check(status%ok(), 'create: '//status%text())
    inquire (file=path//'.tmp', exist=exists)
    call check(exists, 'written under the temporary name while open')
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
    inquire (file=path//'.tmp', exist=exists)
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
    call check(.not. status%ok() .and. index(status%text(), 'no/such/folder/x.h5') > 0, &
               'unwritable path reported: '//status%text())
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
