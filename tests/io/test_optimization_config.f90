!> &optimize's reader (io_optimization_config) takes its default design from
!> the design layer (design_slide_design's table_4_12_design), no copy of its
!> own: an &optimize that gives no design variables reads table 4.12's
!> points, design points, coordinates and bounds exactly; given coordinates
!> are read as the letters x, y, z (1, 2, 3). Its default rides are the
!> design layer's thesis_start_angles, as the declaration of start_angles_deg
!> documents them (docs/inputs.md).
program test_optimization_config
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use design_slide_design, only: slide_design_t, table_4_12_design
  use design_geometry_optimization, only: optimization_setup_t, thesis_start_angles
  use io_declaration, only: declaration_t
  use io_input_declarations, only: declaration, find_declaration
  use io_input, only: input_text_t, input_from_text
  use io_optimization_config, only: read_optimization_config
  use testing, only: check, finish_tests
  implicit none (type, external)

  character(len=1), parameter :: nl = new_line('a')
  type(input_text_t) :: input
  type(optimization_setup_t) :: setup
  type(slide_design_t) :: table
  type(status_t) :: st
  real(wp) :: declared(5)
  type(declaration_t) :: angles
  integer :: stat

  table = table_4_12_design()
  call input_from_text('o.nml', '&optimize radius = 0.6 /', input, st)
  if (st%ok()) call read_optimization_config(input, setup, st)
  call check(st%ok(), 'defaults read: '//st%text())
  if (st%ok()) then
    call check(all(setup%design%points == table%points), 'default points: table 4.12''s')
    call check(all(setup%design%point == table%point), 'default design points: table 4.12''s')
    call check(all(setup%design%coordinate == table%coordinate), 'default design coordinates: table 4.12''s')
    call check(all(setup%design%lower == table%lower) .and. all(setup%design%upper == table%upper), &
               'default bounds: table 4.12''s')
    call check(all(setup%start_angles == thesis_start_angles()), 'default rides: the design layer''s start angles')
  end if
  ! the documented default, in degrees (read back to within a rounding of
  ! the conversion: 1e-12 deg against 30 deg)
  declared = huge(1.0_wp)
  angles = declaration(find_declaration('optimize', 'start_angles_deg'))
  read (angles%default, *, iostat=stat) declared
  call check(stat == 0 .and. all(abs(declared - thesis_start_angles()*180/pi) < 1e-12_wp), &
             'the declared default of start_angles_deg is the design layer''s start angles')

  st = status_t()
  call input_from_text('o.nml', '&optimize'//nl//' n_design = 3, design_point = 2, 3, 5'//nl// &
                       ' design_coordinate = ''z'', ''x'', ''y'''//nl// &
                       ' lower = 2, 4, 8, upper = 3, 6, 10 /', input, st)
  if (st%ok()) call read_optimization_config(input, setup, st)
  call check(st%ok(), 'given design read: '//st%text())
  if (st%ok()) call check(all(setup%design%coordinate == [3, 1, 2]) .and. all(setup%design%point == [3, 4, 6]), &
                          'given coordinates z, x, y are 3, 1, 2')
  call finish_tests('test_optimization_config')
end program test_optimization_config
