!> Every declared input variable (io_declaration), looked up by group and
!> name; the names of a group; and the reference tables of docs/inputs.md
!> (`slidesim --input-reference`), written from the declarations so that
!> the documentation cannot drift from what the readers check.
module io_input_declarations
  use base_text, only: lower
  use io_declaration, only: declaration_t, allowed_text, in_groups
  use io_declarations_ride, only: ride_declarations
  use io_declarations_design, only: design_declarations
  use io_declarations_multibody, only: multibody_declarations
  use io_declarations_geometry, only: geometry_declarations
  implicit none (type, external)
  private
  public :: find_declaration, declared_names, input_reference, declaration, declaration_count, declared_unit

  !> Every declaration, in the order of the reference.
  type(declaration_t), parameter :: declarations(*) = [ride_declarations, design_declarations, multibody_declarations, &
    geometry_declarations]

  !> The groups of the reference, in its order (&water_solver has the
  !> declarations of &solver, and is named in its rows).
  character(len=*), parameter :: reference_groups(*) = [character(len=16) :: 'run', 'solver', 'evaluation', &
    'channel', 'water', 'inlet', 'rider', 'sweep', 'identify_rider', 'identify_water', 'optimize', 'design_elements', 'catalogue', &
    'surface', 'shape', &
    'geometry', 'centerline', 'slide_elements', 'cross_section', 'blended', 'bspline', 'grid', 'point_mass', &
    'pendulum', 'fourbar', 'sled', 'contact_model', 'body', 'contact']
  !> The heading of each (a group read differently by two scenarios names both).
  character(len=*), parameter :: reference_titles(size(reference_groups)) = [character(len=40) :: '&run', &
    '&solver', '&evaluation', '&channel', '&water', '&inlet', '&rider', '&sweep', '&identify (scenario identify_rider)', &
    '&identify (scenario identify_water)', '&optimize', '&design_elements', '&catalogue', &
    '&surface', '&shape', '&geometry', '&centerline', &
    '&slide_elements', '&cross_section', '&blended', '&bspline', '&grid', '&point_mass', &
    '&pendulum', '&fourbar', '&sled', '&contact_model', '&body', '&contact']
  !> A line under a group's heading, where the group needs one.
  character(len=*), parameter :: reference_notes(size(reference_groups)) = [character(len=320) :: '', &
    'The ride''s `&water_solver` (the integration of its water) has the same variables but `accuracy`. '// &
    'Some scenarios '// &
    'start from defaults of their own (the ride, the water, optimize: their pages).', '', &
    'A closed-form tube instead of `&surface` (docs/water.md).', '', &
    'One group per inlet: more water joining along the slide (docs/water.md, "Several inlets"), in order of '// &
    '`arc_length`; the water and the ride.', &
    'Besides these, the parameters of the chosen friction law at the three contacts (docs/inputs.md, '// &
    '"&point_mass"; docs/rider.md): with `''coulomb''`, `mu` (default 0.0724419 here) and '// &
    '`regularization_speed`.', &
    'Each swept variable is a list (`mass = 50, 70, 90`) or a range (`mass_range = 50, 90, 5`: first, '// &
    'last, count); one not swept keeps its `&rider` / `&water` value (docs/sweep.md). In an `optimize` '// &
    'input: the population of a robust optimisation (docs/design.md, "Robust design over a population").', &
    'The rider''s friction from measured wall angles and speeds (docs/design.md).', &
    'The water''s friction from measured flow middles and speeds (docs/design.md).', &
    'The geometry optimisation of a tube slide (thesis 4.7, docs/design.md).', &
    'Element parameters of `&slide_elements` as the design variables of `&optimize` (docs/design.md, '// &
    '"Designs from standard parts").', &
    'The parts an element design may use: the optimum is snapped to them and ridden again (docs/design.md, '// &
    '"Designs from standard parts").', &
    'Besides these, the parameters of the chosen kind (docs/inputs.md, "&surface"; declared with the kind).', &
    'A surface of the contact scenario: the variables of `&surface` and a name (docs/contact.md).', &
    'The geometry groups describe a tube, a slide, a blended or a B-spline surface: the geometry '// &
    'scenario''s input, or `&surface kind` with these groups or its `geometry_file` (docs/geometry.md).', &
    'A tube around a centerline (`&geometry kind = ''tube''`); a value the kind does not use is refused.', &
    'A slide from standard elements (`&geometry kind = ''slide''`, docs/geometry.md); a value an element '// &
    'does not use must be left out or 0 (`''left''` for `direction`).', &
    'The cross-section of a tube or slide: one, or several blended along the centerline (transitions '// &
    'in m of arc length).', &
    'Elementary patches placed, cut and blended along u (`&geometry kind = ''blended''`, thesis 3.73-3.79).', &
    'A B-spline surface fitted to points from a CSV file (`&geometry kind = ''bspline''`).', &
    'The resolution of the geometry scenario''s written grid (docs/geometry.md).', &
    'Besides these, the parameters of the chosen friction law (docs/inputs.md, "&point_mass").', &
    'docs/inputs_multibody.md.', 'docs/inputs_multibody.md.', 'docs/inputs_multibody.md.', &
    'The contact scenario (docs/contact.md).', 'A rigid body of the contact scenario (docs/contact.md).', &
    'A point contact of the contact scenario; besides these, the parameters of the chosen friction law '// &
    '(docs/contact.md).']

contains

  !> The index of the declaration of `name` in `group` (any case); 0: none.
  pure integer function find_declaration(group, name) result(k)
    character(len=*), intent(in) :: group, name
    character(len=:), allocatable :: g, n
    g = lower(trim(group))
    n = lower(trim(name))
    do k = 1, size(declarations)
      if (trim(declarations(k)%name) == n .and. in_groups(g, declarations(k)%groups)) return
    end do
    k = 0
  end function find_declaration

  !> Declaration k (from find_declaration), with the range of the
  !> declaration it names in `range_of`.
  pure function declaration(k) result(d)
    integer, intent(in) :: k
    type(declaration_t) :: d
    integer :: cut, j
    d = declarations(k)
    if (len_trim(d%range_of) == 0) return
    cut = index(trim(d%range_of), ' ')
    j = find_declaration(d%range_of(:cut - 1), d%range_of(cut + 1:))
    if (j == 0) return   ! test_input_declarations: every range_of names a declaration
    d%kind = declarations(j)%kind
    d%low = declarations(j)%low
    d%high = declarations(j)%high
    d%open_low = declarations(j)%open_low
    if (len_trim(d%unit) == 0) d%unit = declarations(j)%unit
  end function declaration

  pure integer function declaration_count()
    declaration_count = size(declarations)
  end function declaration_count

  !> The unit of `name` in `group` (for results that report an input value);
  !> '' when not declared.
  pure function declared_unit(group, name) result(unit)
    character(len=*), intent(in) :: group, name
    character(len=:), allocatable :: unit
    integer :: k
    unit = ''
    k = find_declaration(group, name)
    if (k > 0) unit = trim(declarations(k)%unit)
  end function declared_unit

  !> The names `group` may hold, in the order declared.
  pure function declared_names(group) result(names)
    character(len=*), intent(in) :: group
    character(len=len(declarations%name)), allocatable :: names(:)
    logical :: mask(size(declarations))
    integer :: k
    do k = 1, size(declarations)
      mask(k) = in_groups(lower(trim(group)), declarations(k)%groups)
    end do
    names = pack(declarations%name, mask)
  end function declared_names

  !> The reference tables of every declared group (Markdown, without the
  !> last line's end), as in docs/inputs.md.
  function input_reference() result(text)
    character(len=:), allocatable :: text
    character(len=*), parameter :: nl = new_line('a')
    integer :: g, k
    text = ''
    do g = 1, size(reference_groups)
      if (g > 1) text = text//nl
      text = text//'### '//trim(reference_titles(g))//nl//nl
      if (len_trim(reference_notes(g)) > 0) text = text//trim(reference_notes(g))//nl//nl
      text = text//'| variable | meaning | unit | default | allowed |'//nl//'|---|---|---|---|---|'//nl
      do k = 1, size(declarations)
        if (.not. in_groups(trim(reference_groups(g)), declarations(k)%groups)) cycle
        text = text//row(declaration(k), trim(reference_groups(g)))//nl
      end do
    end do
    text = text(:len(text) - 1)   ! the last line without its end
  end function input_reference

  !> One row of a group's table; a variable shared with other groups says so.
  function row(d, group) result(text)
    type(declaration_t), intent(in) :: d
    character(len=*), intent(in) :: group
    character(len=:), allocatable :: text, unit, meaning, others, default
    integer :: i, start
    unit = trim(d%unit)
    if (len(unit) == 0) unit = '–'
    meaning = trim(d%meaning)
    if (len_trim(d%shape) > 0) meaning = meaning//' ('//trim(d%shape)//')'
    ! the other groups that hold the same declaration
    others = ''
    start = 1
    do i = 1, len_trim(d%groups) + 1
      if (i > len_trim(d%groups) .or. d%groups(i:i) == ' ') then
        if (i > start) then
          if (d%groups(start:i - 1) /= group) then
            if (len(others) > 0) others = others//', '
            others = others//'&'//d%groups(start:i - 1)
          end if
        end if
        start = i + 1
      end if
    end do
    if (len(others) > 0) meaning = meaning//'; the same variable as in '//others
    if (len_trim(d%range_of) > 0) meaning = meaning//'; the range of &'//trim(d%range_of)
    default = trim(d%default)
    if (default /= 'none' .and. index(default, '`') == 0) default = '`'//default//'`'
    text = '| `'//trim(d%name)//'` | '//meaning//' | '//unit//' | '//default//' | '//allowed_text(d)//' |'
  end function row
end module io_input_declarations
