!> The generator of the --default-input templates (io_templates): a
!> variable's comment is its declaration's unit, meaning and range, the
!> default only where the value shown differs; a surface kind's and a
!> friction law's parameters come from the kind's declaration; commented-out
!> variables, aligned columns and continued values as the spec says; and a
!> spec that names an undeclared variable, or leaves a variable without a
!> usable default valueless, is an error naming the spec's line.
program test_templates
  use io_templates, only: template_from_spec
  use testing, only: check, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')

  call comments_from_declarations()
  call kind_parameters()
  call layout()
  call spec_errors()
  call finish_tests('test_templates')

contains

  subroutine comments_from_declarations()
    character(len=:), allocatable :: text, error
    call template_from_spec('ride', 'a ride.'//nl//'&rider ! the rider'//nl//'mass = 70'//nl//'height'//nl// &
                            'mu = 0.0724419 ! a note long enough to be wrapped under the comment''s first line', text, &
                            error)
    call check(error == '', 'a valid spec: no error ('//error//')')
    call check(index(text, '! Template of the ride scenario (slidesim --default-input ride): a ride.') == 1, &
               'the header names the scenario and holds the introduction')
    call check(index(text, '&rider                             ! the rider'//nl) > 0, 'the group and its note')
    call check(index(text, '  mass = 70                        ! kg, 10 .. 300; body mass (thesis table 4.10); '// &
                     'default 68.5'//nl) > 0, 'unit, declared range, meaning, and the default where it differs')
    call check(index(text, '  height = 1.78                    ! m, 0.5 .. 2.5; body height (thesis table 4.10)'// &
                     nl) > 0, 'a variable without a value shows its declared default (and not "default")')
    call check(index(text, '  mu = 0.0724419                   ! > 0 .. 10; friction coefficient; a note long enough '// &
                     'to be wrapped under'//nl//repeat(' ', 35)//'! the comment''s first line'//nl) > 0, &
               'a dimensionless variable (the rider''s Coulomb law''s mu): no unit; the comment wrapped under '// &
               'itself; the spec''s note last')
    call check(text(len(text) - 1:) == '/'//nl, 'the group is closed')
  end subroutine comments_from_declarations

  subroutine kind_parameters()
    character(len=:), allocatable :: text, error
    call template_from_spec('point_mass', '&surface'//nl//'kind = ''ellipsoid'''//nl//'a = 2.0'//nl// &
                            '- point_a = 0.0, 0.0, 0.0 ! planes only'//nl//'&point_mass'//nl// &
                            'friction = ''coulomb'''//nl//'friction_coefficient = 0.2', text, error)
    call check(error == '', 'kind parameters: no error ('//error//')')
    call check(index(text, '  kind = ''ellipsoid''               ! one of plane, ellipsoid,') > 0, &
               'the surface kinds from the registry')
    call check(index(text, '  a = 2.0                          ! m, 0.001 .. 10000; semi-axis along x; default 1'// &
                     nl) > 0, 'a parameter of the chosen surface kind, by its declaration')
    call check(index(text, '  ! point_a = 0.0, 0.0, 0.0        ! m, -1e6 .. 1e6; point A (3 values); planes only'// &
                     nl) > 0, 'commented out: a parameter of another kind')
    call check(index(text, '  friction = ''coulomb''             ! one of none, coulomb,') > 0, &
               'the friction laws from the registry')
    call check(index(text, '  friction_coefficient = 0.2       ! > 0 .. 10; friction coefficient; default none '// &
                     '(required)'//nl) > 0, 'the point mass''s friction_coefficient is the law''s mu')
  end subroutine kind_parameters

  subroutine layout()
    character(len=:), allocatable :: text, error
    integer :: first, second
    call template_from_spec('ride', '&water starts this line of the introduction, not a group'//nl// &
                            '&rider'//nl//'| limit_max = 10.0, 8.0'//nl//'| limit_unit = ''km/h'', ''m/s'''//nl// &
                            '&water'//nl//'stations = 10.0, 20.0,'//nl//'+ 30.0', text, error)
    call check(error == '', 'layout: no error ('//error//')')
    call check(index(text, ': &water starts') > 0 .and. index(text, nl//'&water starts') == 0, &
               'an introduction''s line that starts with a group''s name stays in the introduction')
    first = index(text, '  limit_max  = 10.0,   8.0  ')
    second = index(text, '  limit_unit = ''km/h'', ''m/s''')
    call check(first > 0 .and. second > 0, 'aligned: names and values in columns')
    call check(index(text(first:), '!') == index(text(second:), '!'), 'aligned: the comments in one column')
    call check(index(text, nl//'  stations = 10.0, 20.0,           ! m, 0 .. 1e6;') > 0 .and. &
               index(text, nl//'             30.0'//nl) > 0, 'a continued value: the rest under the first')
  end subroutine layout

  subroutine spec_errors()
    character(len=:), allocatable :: text, error
    call template_from_spec('ride', 'intro'//nl//'&rider'//nl//'mass'//nl//'massive = 3', text, error)
    call check(index(error, 'ride.spec:') == 1 .and. index(error, '&rider: massive is not declared') > 0, &
               'an undeclared variable is an error of the spec: '//error)
    call template_from_spec('water', '&water'//nl//'stations', text, error)
    call check(index(error, '&water: stations: its default "none" is not a value: give one') > 0, &
               'a default that is not a value needs one: '//error)
    call template_from_spec('water', 'only an introduction', text, error)
    call check(index(error, 'no group') > 0, 'a spec without a group: '//error)
    call template_from_spec('water', '&water'//nl//'| f1 = 1.0'//nl//'+ 2.0', text, error)
    call check(index(error, 'continues only') > 0, 'a "+" line after a "|" line: '//error)
  end subroutine spec_errors
end program test_templates
