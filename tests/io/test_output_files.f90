!> io_output_files: no output may be a file the run reads or another output
!> (by identity, through links, and by resolved path for files not there
!> yet), and text_output_t puts a file in place only when it is complete.
!> Devices, FIFOs, sockets and a full disk: tests/cli/output_files.sh (on
!> private nodes and a tmpfs of its own).
program test_output_files
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use io_system, only: create_unique_file, remove_file
  use io_output_files, only: start_run_files, note_input_file, claim_output, text_output_t
  use testing, only: check, finish_tests
  implicit none (type, external)

  character(len=:), allocatable :: input, output, error, folder

  call create_unique_file('/tmp/slidesim_test_output_files', '.nml', input, error)
  call check(len(input) > 0, 'a file to read: '//error)
  folder = input(:index(input, '/', back=.true.))
  output = input//'.out'
  call output_is_input()
  call read_after_claim()
  call outputs_collide()
  call text_in_place()
  call remove_file(input)
  call remove_file(output)
  call finish_tests('test_output_files')

contains

  subroutine output_is_input()
    type(status_t) :: status
    character(len=:), allocatable :: link
    call start_run_files()
    call note_input_file(input, 'input file', status)
    call check(status%ok(), 'a file read is noted')
    call claim_output(input, '-o '//input, 'the result file', status)
    call check(status%code == STATUS_INVALID_INPUT .and. index(status%text(), 'would overwrite the input file "'// &
               input//'", which this run reads') > 0, 'the input as the output is refused: '//status%text())
    ! a symbolic link to it names the same file
    link = input//'.link'
    call execute_command_line('ln -s '//input//' '//link)
    status = status_t()
    call claim_output(link, '-o '//link, 'the result file', status)
    call check(status%code == STATUS_INVALID_INPUT, 'a link to the input as the output is refused')
    call remove_file(link)
    status = status_t()
    call claim_output(output, '-o '//output, 'the result file', status)
    call check(status%ok(), 'another file is claimed: '//status%text())
  end subroutine output_is_input

  !> A file read after the outputs were claimed (a geometry file) is refused where it is read.
  subroutine read_after_claim()
    type(status_t) :: status
    integer :: unit
    call start_run_files()
    call claim_output(output, '--summary-json '//output, 'the summary JSON', status)
    call check(status%ok(), 'a new file is claimed: '//status%text())
    open (newunit=unit, file=output, status='replace', action='write')
    write (unit, '(a)') '&surface /'
    close (unit)
    call note_input_file(output, 'input file', status)
    call check(status%code == STATUS_INVALID_INPUT .and. index(status%text(), 'is the file the summary JSON '// &
               '(--summary-json '//output//') would overwrite') > 0, 'a claimed file read later is refused: '// &
               status%text())
  end subroutine read_after_claim

  !> Two outputs on one path, spelt differently and not there yet.
  subroutine outputs_collide()
    type(status_t) :: status
    character(len=:), allocatable :: fresh
    call start_run_files()
    fresh = folder//'slidesim_test_output_files_new.h5'
    call remove_file(fresh)
    call claim_output(fresh, '-o '//fresh, 'the result file', status)
    call check(status%ok(), 'a new path is claimed: '//status%text())
    call claim_output(folder//'./'//fresh(len(folder) + 1:), '--summary-json', 'the summary JSON', status)
    call check(status%code == STATUS_INVALID_INPUT .and. index(status%text(), 'would be written to the same '// &
               'file as the result file') > 0, 'one path spelt twice is refused: '//status%text())
  end subroutine outputs_collide

  !> Nothing at the path until finish; then the whole text, no temporary left.
  subroutine text_in_place()
    type(status_t) :: status
    type(text_output_t) :: text
    character(len=200) :: line
    integer :: unit, ios
    logical :: exists
    call remove_file(output)
    call text%create(output, 'the test file', status)
    call check(status%ok(), 'created: '//status%text())
    call text%write_line('first')
    call text%write(repeat('x', 70000))   ! more than the buffer
    call text%write_line('')
    inquire (file=output, exist=exists)
    call check(.not. exists, 'nothing at the path before finish')
    call text%finish(status)
    call check(status%ok(), 'finished: '//status%text())
    inquire (file=text%temporary_name(), exist=exists)
    call check(.not. exists, 'no temporary file left')
    open (newunit=unit, file=output, status='old', action='read', iostat=ios)
    call check(ios == 0, 'the file is in place')
    if (ios /= 0) return
    read (unit, '(a)') line
    call check(line == 'first', 'its first line')
    read (unit, '(a)') line
    call check(line(:3) == 'xxx' .and. line(200:200) == 'x', 'its second line')
    close (unit)
  end subroutine text_in_place
end program test_output_files
