!> XDMF files for ParaView and VisIt next to a result file, in the XDMF 2
!> form that every reader ParaView has reads alike (the Xdmf3 readers it
!> picks by itself for File > Open, and the "XDMF Reader"): checked with
!> each by tests/cli/xdmf_files.sh.
!> - The arrays are not copied: a DataItem names a dataset of the result
!>   file (Format="HDF", `<name>.h5:/group/dataset`, the result's final file
!>   name without folder: the two files sit side by side and move together).
!>   ParaView 5.11's Xdmf3 readers read only whole datasets (no X_Y_Z
!>   geometry, JOIN or hyperslab: 0 points), so a grid whose points or
!>   values the result holds in another layout (a surface's x, y, z; the
!>   water band's two edges) gets them in that layout under /xdmf (the
!>   same numbers); they resolve a reference against the .xmf's folder and
!>   abort (SIGABRT) when the .xmf is named without one (`ride.xmf` gives
!>   `ride.xmfride.h5`): open `./ride.xmf` or a full path (File > Open does).
!>   Only what a grid needs at each time step (a few points, a box's corners)
!>   and the connectivities are inline (Format="XML"). A ':' cannot stand in
!>   a reference (no escape exists; the "XDMF Reader" splits it at the last
!>   ':', the Xdmf3 readers at the first): the result file's name and every
!>   name that becomes a referenced group (a body's, a contact's) are refused
!>   with one (colon_refusal).
!> - A surface grid is a structured grid (2DSMesh) with XYZ points; a path a
!>   polyline with explicit connectivity (the Xdmf3 readers make no cell
!>   without it), with the real (n) and (n, 3) datasets of its groups as
!>   node scalars and vectors; the water band a 2 x n structured grid; a
!>   set of points (the landings of a flight) a polyvertex.
!> - Anything moving makes the file one temporal collection of spatial
!>   collections (at most max_steps steps: every k-th sample and the last):
!>   the Xdmf3 readers drop a grid that stands beside a temporal collection.
!>   The first step holds the grids that do not move; the later steps
!>   include them (XInclude by position, read by both readers) instead of
!>   repeating their values.
!> Layout: docs/outputs.md ("ParaView and VisIt").
module io_xdmf
  use base_kinds, only: wp
  use base_text, only: format_integer, format_real
  use base_scientific_text, only: scientific_text
  use base_status, only: status_t, STATUS_OK
  use io_hdf5, only: result_file_t
  implicit none (type, external)
  private
  public :: xdmf_t, xdmf_path, attach_surface_view, body_shape_t, colon_refusal

  integer, parameter :: max_steps = 200   ! time steps of a temporal collection
  integer, parameter :: per_line = 6      ! values per line of a DataItem
  integer, parameter :: width = 17        ! characters per value: a blank and ES16.8E3

  !> Text that grows by doubling (appending stays linear).
  type :: text_t
    character(len=:), allocatable :: s
    integer :: used = 0
  end type text_t

  !> A shape a body carries, as a grid of points in the body's axes (m):
  !> drawn moving with the body (moving_grid).
  type :: body_shape_t
    character(len=:), allocatable :: body, shape
    real(wp), allocatable :: points(:, :, :)   !< 3 x n1 x n2
  end type body_shape_t

  type :: xdmf_t
    private
    type(text_t) :: fixed                   !< the grids that do not move
    integer :: n_fixed = 0
    integer :: n_series = 0                 !< samples of the moving grids' series (0: none yet)
    real(wp), allocatable :: step_time(:)   !< s, the kept time steps
    integer, allocatable :: step_row(:)     !< their samples in the series
    type(text_t), allocatable :: steps(:)   !< the moving grids of each kept step
    type(status_t) :: written                !< of the arrays added to the result under /xdmf
  contains
    procedure :: start => xdmf_start
    procedure :: surface => xdmf_surface
    procedure :: polyline => xdmf_polyline
    procedure :: point_set => xdmf_point_set
    procedure :: band => xdmf_band
    procedure :: moving_points => xdmf_moving_points
    procedure :: moving_box => xdmf_moving_box
    procedure :: moving_grid => xdmf_moving_grid
    procedure :: attach => xdmf_attach
  end type xdmf_t

contains

  !> The XDMF file next to a result: `<name>.xmf` for `<name>.h5`, else the
  !> result's name with `.xmf` appended.
  !> Why `name` cannot name a result file or a group that the XDMF view
  !> references ('' when it can): a ':' in it (module comment).
  pure function colon_refusal(name) result(why)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: why
    why = ''
    if (index(name, ':') > 0) why = 'must not contain '':'': the XDMF view beside the result names each dataset '// &
      'as "file.h5:/group/dataset", and ParaView''s readers split that at a '':'''
  end function colon_refusal

  pure function xdmf_path(h5_path) result(path)
    character(len=*), intent(in) :: h5_path
    character(len=:), allocatable :: path
    integer :: n
    n = len_trim(h5_path)
    if (n > 3) then
      if (h5_path(n - 2:n) == '.h5') then
        path = h5_path(:n - 3)//'.xmf'
        return
      end if
    end if
    path = h5_path(:n)//'.xmf'
  end function xdmf_path

  !> Begins an empty view.
  subroutine xdmf_start(self)
    class(xdmf_t), intent(inout) :: self
    self%fixed%used = 0
    self%n_fixed = 0
    self%n_series = 0
    if (allocated(self%steps)) deallocate (self%steps)
    self%written = status_t()
  end subroutine xdmf_start

  !> The surface grid of io_surface_grid (group/x, y, z of shape (n_u, n_v)):
  !> its points as /xdmf/<group>/points (n_u, n_v, 3), added to the result.
  subroutine xdmf_surface(self, file, name, group)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: name, group
    integer, allocatable :: dims(:)
    real(wp), allocatable :: x(:), y(:), z(:)
    character(len=:), allocatable :: points
    dims = file%shape_of(group//'/x')
    if (size(dims) /= 2) return
    points = '/xdmf'//group//'/points'
    if (.not. same_shape(file%shape_of(points), [dims, 3])) then
      x = file%values_of(group//'/x')
      y = file%values_of(group//'/y')
      z = file%values_of(group//'/z')
      if (size(x) /= product(dims) .or. size(y) /= size(x) .or. size(z) /= size(x)) return
      call file%write_array3(points, reshape(transpose(reshape([x, y, z], [size(x), 3])), [3, dims(2), dims(1)]), &
                             file%units_of(group//'/x'), 'the points of the XDMF view''s surface grid: '//group// &
                             '/x, y and z side by side', self%written)
      if (.not. self%written%ok()) return
    end if
    call add(self%fixed, '<Grid Name="'//escaped(name)//'" GridType="Uniform">')
    call add(self%fixed, '  <Topology TopologyType="2DSMesh" Dimensions="'//dims_text(dims)//'"/>')
    call add(self%fixed, '  <Geometry GeometryType="XYZ">')
    call referenced_item(self%fixed, file, [dims, 3], points, .true.)
    call add(self%fixed, '  </Geometry>')
    call add(self%fixed, '</Grid>')
    self%n_fixed = self%n_fixed + 1
  end subroutine xdmf_surface

  !> A polyline through the rows of `points` (shape (n, 3)) with the real
  !> datasets of `group` of shape (n) or (n, 3) as node attributes, and
  !> those of `more` (e.g. the rider's own beside its contact's) whose names
  !> `group` does not have; then each dataset of `fields` (shape (n), real or
  !> integer, e.g. a contact's open state) that was written, named by
  !> `field_names`.
  subroutine xdmf_polyline(self, file, name, points, group, more, field_names, fields)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, points, group
    character(len=*), intent(in), optional :: more
    character(len=*), intent(in), optional :: field_names(:), fields(:)
    call point_grid(self, file, name, points, group, .true., more, field_names, fields)
  end subroutine xdmf_polyline

  !> The rows of `points` (shape (k, 3), k >= 1) as a set of points (a
  !> polyvertex) with the datasets of `group` of shape (k) or (k, 3), real or
  !> integer, as node attributes (e.g. the impacts of a flight).
  subroutine xdmf_point_set(self, file, name, points, group)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, points, group
    call point_grid(self, file, name, points, group, .false.)
  end subroutine xdmf_point_set

  !> The grid of xdmf_polyline (`polyline`: the rows joined in order, real
  !> attributes) or of xdmf_point_set (the rows alone, real and integer
  !> attributes).
  subroutine point_grid(self, file, name, points, group, polyline, more, field_names, fields)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, points, group
    logical, intent(in) :: polyline
    character(len=*), intent(in), optional :: more
    character(len=*), intent(in), optional :: field_names(:), fields(:)
    integer, allocatable :: dims(:)
    character(len=:), allocatable :: taken
    integer :: k
    dims = file%shape_of(points)
    if (size(dims) /= 2) return
    if (dims(1) < merge(2, 1, polyline) .or. dims(2) /= 3) return
    call add(self%fixed, '<Grid Name="'//escaped(name)//'" GridType="Uniform">')
    if (polyline) then
      call add(self%fixed, '  <Topology TopologyType="Polyline" NodesPerElement="'//format_integer(dims(1))// &
               '" NumberOfElements="1">')
      call add(self%fixed, '    <DataItem Dimensions="1 '//format_integer(dims(1))//'" NumberType="Int" Format="XML">')
    else
      call add(self%fixed, '  <Topology TopologyType="Polyvertex" NodesPerElement="1" NumberOfElements="'// &
               format_integer(dims(1))//'">')
      call add(self%fixed, '    <DataItem Dimensions="'//format_integer(dims(1))//' 1" NumberType="Int" Format="XML">')
    end if
    call integer_lines(self%fixed, [(k, k = 0, dims(1) - 1)])
    call add(self%fixed, '    </DataItem>')
    call add(self%fixed, '  </Topology>')
    call add(self%fixed, '  <Geometry GeometryType="XYZ">')
    call referenced_item(self%fixed, file, dims, points, .true.)
    call add(self%fixed, '  </Geometry>')
    taken = '/'
    call group_attributes(self%fixed, file, group, points, dims(1), .not. polyline, taken)
    if (present(more)) call group_attributes(self%fixed, file, more, points, dims(1), .false., taken)
    if (present(fields) .and. present(field_names)) then
      do k = 1, min(size(fields), size(field_names))
        if (.not. same_shape(file%shape_of(trim(fields(k))), [dims(1)])) cycle
        if (.not. holds_numbers(file, trim(fields(k)))) cycle
        call referenced_attribute(self%fixed, file, trim(field_names(k)), 'Scalar', [dims(1)], trim(fields(k)))
      end do
    end if
    call add(self%fixed, '</Grid>')
    self%n_fixed = self%n_fixed + 1
  end subroutine point_grid

  !> The datasets of `group` of shape (n) or (n, 3) as node attributes of a
  !> grid of n points (not `points` itself, nor a name in `taken`, which
  !> gains each one added): the real ones, and with `integers` the integer
  !> ones too.
  subroutine group_attributes(text, file, group, points, n, integers, taken)
    type(text_t), intent(inout) :: text
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: group, points
    integer, intent(in) :: n
    logical, intent(in) :: integers
    character(len=:), allocatable, intent(inout) :: taken
    character(len=:), allocatable :: names(:), base
    integer, allocatable :: d(:)
    integer :: k
    names = file%names_in(group)
    do k = 1, size(names)
      if (trim(names(k)) == points) cycle
      if (.not. (file%is_real(trim(names(k))) .or. integers)) cycle
      d = file%shape_of(trim(names(k)))
      if (size(d) == 0) cycle
      if (d(1) /= n) cycle
      base = base_name(trim(names(k)))
      if (index(taken, '/'//base//'/') > 0) cycle
      if (.not. holds_numbers(file, trim(names(k)))) cycle   ! not text
      if (size(d) == 1) then
        call referenced_attribute(text, file, base, 'Scalar', d, trim(names(k)))
      else if (size(d) == 2) then
        if (d(2) /= 3) cycle
        call referenced_attribute(text, file, base, 'Vector', d, trim(names(k)))
      end if
      taken = taken//base//'/'
    end do
  end subroutine group_attributes

  !> The band between two edges (shape (n, 3) each) as a 2 x n structured
  !> grid; `fields` (shape (n)) on both edges' nodes. Added to the result
  !> under /xdmf/<the first edge's group>/band: points (2 n, 3), the first
  !> edge's rows then the second's, and each field twice over (2 n).
  subroutine xdmf_band(self, file, name, first_edge, second_edge, fields)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: name, first_edge, second_edge
    character(len=*), intent(in) :: fields(:)
    integer, allocatable :: dims(:)
    real(wp), allocatable :: values(:)
    character(len=:), allocatable :: band, twice
    integer :: k
    dims = file%shape_of(first_edge)
    if (size(dims) /= 2) return
    if (dims(1) < 2 .or. dims(2) /= 3) return
    if (.not. same_shape(file%shape_of(second_edge), dims)) return
    band = '/xdmf'//first_edge(:index(first_edge, '/', back=.true.))//'band'
    if (.not. same_shape(file%shape_of(band//'/points'), [2*dims(1), 3])) then
      call file%write_matrix(band//'/points', reshape([file%values_of(first_edge), file%values_of(second_edge)], &
                                                      [3, 2*dims(1)]), file%units_of(first_edge), &
                             'the points of the XDMF view''s band: the rows of '//first_edge//', then of '// &
                             second_edge, self%written)
      if (.not. self%written%ok()) return
    end if
    call add(self%fixed, '<Grid Name="'//escaped(name)//'" GridType="Uniform">')
    call add(self%fixed, '  <Topology TopologyType="2DSMesh" Dimensions="2 '//format_integer(dims(1))//'"/>')
    call add(self%fixed, '  <Geometry GeometryType="XYZ">')
    call referenced_item(self%fixed, file, [2*dims(1), 3], band//'/points', .true.)
    call add(self%fixed, '  </Geometry>')
    do k = 1, size(fields)
      if (.not. same_shape(file%shape_of(trim(fields(k))), [dims(1)])) cycle
      twice = band//'/'//base_name(trim(fields(k)))
      if (.not. same_shape(file%shape_of(twice), [2*dims(1)])) then
        values = file%values_of(trim(fields(k)))
        if (size(values) /= dims(1)) cycle
        call file%write_vector(twice, [values, values], file%units_of(trim(fields(k))), trim(fields(k))// &
                               ' twice over, on both edges of the XDMF view''s band', self%written)
        if (.not. self%written%ok()) exit
      end if
      call referenced_attribute(self%fixed, file, base_name(trim(fields(k))), 'Scalar', [2*dims(1)], twice)
    end do
    call add(self%fixed, '</Grid>')
    self%n_fixed = self%n_fixed + 1
  end subroutine xdmf_band

  !> Points moving over time: at each kept time step one point per dataset
  !> in `points` (each of shape (n, 3)), joined by a polyline when `connect`;
  !> node scalars(j, k, i) of point k at sample i named scalar_names(j).
  subroutine xdmf_moving_points(self, file, name, time, points, connect, scalar_names, scalars)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: time(:)
    character(len=*), intent(in) :: points(:)
    logical, intent(in) :: connect
    character(len=*), intent(in), optional :: scalar_names(:)
    real(wp), intent(in), optional :: scalars(:, :, :)
    real(wp), allocatable :: xyz(:, :)   ! 3 n x m: every dataset's rows
    real(wp), allocatable :: values(:)
    integer :: m, k, s, i, j
    logical :: with_scalars
    m = size(points)
    with_scalars = .false.
    if (present(scalars) .and. present(scalar_names)) then
      if (any(shape(scalars) /= [size(scalar_names), m, size(time)])) return
      with_scalars = .true.
    end if
    if (m < 1 .or. .not. steps_for(self, time)) return
    allocate (xyz(3*size(time), m))
    do k = 1, m
      values = file%values_of(trim(points(k)))
      if (size(values) /= 3*size(time)) return
      xyz(:, k) = values
    end do
    do s = 1, size(self%step_row)
      i = self%step_row(s)
      associate (t => self%steps(s))
        call add(t, '  <Grid Name="'//escaped(name)//'" GridType="Uniform">')
        if (connect .and. m > 1) then
          call add(t, '  <Topology TopologyType="Polyline" NodesPerElement="'//format_integer(m)// &
                   '" NumberOfElements="1">')
          call add(t, '    <DataItem Dimensions="1 '//format_integer(m)//'" NumberType="Int" Format="XML">')
        else
          call add(t, '  <Topology TopologyType="Polyvertex" NodesPerElement="1" NumberOfElements="'// &
                   format_integer(m)//'">')
          call add(t, '    <DataItem Dimensions="'//format_integer(m)//' 1" NumberType="Int" Format="XML">')
        end if
        call integer_lines(t, [(k, k = 0, m - 1)])
        call add(t, '    </DataItem>')
        call add(t, '  </Topology>')
        call add(t, '  <Geometry GeometryType="XYZ">')
        call data_item(t, [m, 3], reshape(xyz(3*i - 2:3*i, :), [3*m]))
        call add(t, '  </Geometry>')
        if (with_scalars) then
          do j = 1, size(scalar_names)
            call attribute(t, trim(scalar_names(j)), 'Scalar', 'Node', [m], scalars(j, :, i))
          end do
        end if
        call add(t, '  </Grid>')
      end associate
    end do
  end subroutine xdmf_moving_points

  !> A box moving over time (a body drawn as a solid): at sample i its
  !> centre(:, i) and axes(:, k, i) (orthonormal columns), half its edge along
  !> axis k half(k); 12 triangles facing outwards. Cell data: scalars(j, i)
  !> named scalar_names(j), vectors(:, j, i) named vector_names(j).
  subroutine xdmf_moving_box(self, name, time, centre, axes, half, scalar_names, scalars, vector_names, vectors)
    class(xdmf_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: time(:), centre(:, :), axes(:, :, :), half(3)
    character(len=*), intent(in) :: scalar_names(:), vector_names(:)
    real(wp), intent(in) :: scalars(:, :), vectors(:, :, :)
    ! the corners 0..7 are (-/+ x) + 2 (-/+ y) + 4 (-/+ z); each face as two
    ! triangles ordered anticlockwise seen from outside
    integer, parameter :: triangles(36) = [0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, &
                                           2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6]
    real(wp) :: corners(3, 0:7)
    type(text_t) :: topology
    integer :: s, i, c, j
    if (.not. steps_for(self, time)) return
    call add(topology, '  <Topology TopologyType="Triangle" NumberOfElements="12">')
    call add(topology, '    <DataItem Dimensions="12 3" NumberType="Int" Format="XML">')
    call integer_lines(topology, triangles)
    call add(topology, '    </DataItem>')
    call add(topology, '  </Topology>')
    do s = 1, size(self%step_row)
      i = self%step_row(s)
      do c = 0, 7
        corners(:, c) = centre(:, i) + merge(1, -1, btest(c, 0))*half(1)*axes(:, 1, i) &
                        + merge(1, -1, btest(c, 1))*half(2)*axes(:, 2, i) &
                        + merge(1, -1, btest(c, 2))*half(3)*axes(:, 3, i)
      end do
      associate (t => self%steps(s))
        call add(t, '  <Grid Name="'//escaped(name)//'" GridType="Uniform">')
        call add(t, topology%s(:topology%used - 1))
        call add(t, '  <Geometry GeometryType="XYZ">')
        call data_item(t, [8, 3], reshape(corners, [24]))
        call add(t, '  </Geometry>')
        ! a body's values are the same on its 12 cells: formatted once
        do j = 1, size(scalar_names)
          call add(t, '  <Attribute Name="'//escaped(trim(scalar_names(j)))//'" AttributeType="Scalar" Center="Cell">')
          call repeated_item(t, [12], [scalars(j, i)], 12)
          call add(t, '  </Attribute>')
        end do
        do j = 1, size(vector_names)
          call add(t, '  <Attribute Name="'//escaped(trim(vector_names(j)))//'" AttributeType="Vector" Center="Cell">')
          call repeated_item(t, [12, 3], vectors(:, j, i), 12)
          call add(t, '  </Attribute>')
        end do
        call add(t, '  </Grid>')
      end associate
    end do
  end subroutine xdmf_moving_box

  !> A grid of points fixed in a moving body (points(:, i, j) in its axes)
  !> as a structured grid: at sample k, origin(:, k) + rotation(:, :, k) p.
  subroutine xdmf_moving_grid(self, name, time, points, rotation, origin)
    class(xdmf_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: time(:), points(:, :, :), rotation(:, :, :), origin(:, :)
    real(wp), allocatable :: body(:, :), moved(:)
    integer :: s, k, n, j, i
    real(wp) :: total
    n = size(points, 2)*size(points, 3)
    if (n < 4 .or. .not. steps_for(self, time)) return
    body = reshape(points, [3, n])
    allocate (moved(3*n))
    do s = 1, size(self%step_row)
      k = self%step_row(s)
      ! rotation p + origin, the sums in the order of the inlined matmul of
      ! a Release build (from 0, over the columns; the .xmf stays the same),
      ! without its temporaries and its memset per point
      do j = 1, n
        do i = 1, 3
          total = 0
          total = total + rotation(i, 1, k)*body(1, j)
          total = total + rotation(i, 2, k)*body(2, j)
          total = total + rotation(i, 3, k)*body(3, j)
          moved(3*(j - 1) + i) = total + origin(i, k)
        end do
      end do
      associate (t => self%steps(s))
        call add(t, '  <Grid Name="'//escaped(name)//'" GridType="Uniform">')
        ! points(:, i, j): i runs fastest, the last of XDMF's dimensions
        call add(t, '  <Topology TopologyType="2DSMesh" Dimensions="'//format_integer(size(points, 3))//' '// &
                 format_integer(size(points, 2))//'"/>')
        call add(t, '  <Geometry GeometryType="XYZ">')
        call data_item(t, [n, 3], moved)
        call add(t, '  </Geometry>')
        call add(t, '  </Grid>')
      end associate
    end do
  end subroutine xdmf_moving_grid

  !> The kept steps of a series of times (made by the first moving grid;
  !> false for an empty series or one of another length than the first's:
  !> every moving grid of a file follows one series).
  logical function steps_for(self, time) result(ok)
    type(xdmf_t), intent(inout) :: self
    real(wp), intent(in) :: time(:)
    integer :: n, stride, s, kept
    n = size(time)
    ok = n >= 1 .and. (self%n_series == 0 .or. self%n_series == n)
    if (.not. ok .or. self%n_series == n) return
    self%n_series = n
    stride = (n + max_steps - 1)/max_steps
    self%step_row = [(s, s = 1, n, stride)]
    if (self%step_row(size(self%step_row)) /= n) self%step_row = [self%step_row, n]
    ! records that share a time (a switch: the state before it and after,
    ! e.g. a contact's lift-off) make one step, the later record's: the
    ! readers want increasing times
    kept = 1
    do s = 2, size(self%step_row)
      if (time(self%step_row(s)) > time(self%step_row(kept))) kept = kept + 1
      self%step_row(kept) = self%step_row(s)
    end do
    self%step_row = self%step_row(:kept)
    self%step_time = time(self%step_row)
    allocate (self%steps(size(self%step_row)))
  end function steps_for

  !> Closes the XML and hands it to the result file, which writes it next to
  !> itself (xdmf_path) as it finishes: both files are kept, or neither.
  subroutine xdmf_attach(self, file, status)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(inout) :: file
    !> nothing is attached to a file whose writes failed (gains the failure
    !> of an array added under /xdmf)
    type(status_t), intent(inout) :: status
    type(text_t) :: xml
    integer :: s, k
    if (status%ok() .and. self%written%code /= STATUS_OK) status = self%written
    if (.not. status%ok()) return
    call add(xml, '<?xml version="1.0" ?>')
    call add(xml, '<Xdmf xmlns:xi="http://www.w3.org/2001/XInclude" Version="2.0">')
    call add(xml, '<Domain>')
    if (self%n_series == 0) then
      if (self%fixed%used > 0) call add(xml, self%fixed%s(:self%fixed%used - 1))
    else
      call add(xml, '<Grid Name="time steps" GridType="Collection" CollectionType="Temporal">')
      do s = 1, size(self%step_row)
        call add(xml, '<Grid Name="step '//format_integer(s)//'" GridType="Collection" CollectionType="Spatial">')
        call add(xml, '  <Time Value="'//format_real(self%step_time(s))//'"/>')
        if (s == 1) then
          if (self%fixed%used > 0) call add(xml, self%fixed%s(:self%fixed%used - 1))
        else
          do k = 1, self%n_fixed
            call add(xml, '  <xi:include xpointer="xpointer(/Xdmf/Domain/Grid/Grid[1]/Grid['// &
                     format_integer(k)//'])"/>')
          end do
        end if
        if (self%steps(s)%used > 0) call add(xml, self%steps(s)%s(:self%steps(s)%used - 1))
        call add(xml, '</Grid>')
      end do
      call add(xml, '</Grid>')
    end if
    call add(xml, '</Domain>')
    call add(xml, '</Xdmf>')
    call file%add_companion(xdmf_path(file%final_path()), xml%s(:xml%used))
  end subroutine xdmf_attach

  !> The view of one surface grid alone (`dataset`, e.g. the slide's
  !> '/geometry/surface' of the identification scenarios), named `name`.
  subroutine attach_surface_view(file, name, dataset, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: name, dataset
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    call xdmf%start()
    call xdmf%surface(file, name, dataset)
    call xdmf%attach(file, status)
  end subroutine attach_surface_view

  subroutine add(text, line)
    type(text_t), intent(inout) :: text
    character(len=*), intent(in) :: line
    character(len=:), allocatable :: grown
    integer :: n
    n = text%used + len(line) + 1
    if (.not. allocated(text%s)) allocate (character(len=max(4096, 2*n)) :: text%s)
    if (n > len(text%s)) then
      allocate (character(len=max(2*len(text%s), n)) :: grown)
      grown(:text%used) = text%s(:text%used)
      call move_alloc(grown, text%s)
    end if
    text%s(text%used + 1:n - 1) = line
    text%s(n:n) = new_line('a')
    text%used = n
  end subroutine add

  !> An attribute of `kind` (Scalar, Vector) centred on `center` (Node, Cell).
  subroutine attribute(text, name, kind, center, dims, values)
    type(text_t), intent(inout) :: text
    character(len=*), intent(in) :: name, kind, center
    integer, intent(in) :: dims(:)
    real(wp), intent(in) :: values(:)
    call add(text, '  <Attribute Name="'//escaped(name)//'" AttributeType="'//kind//'" Center="'//center//'">')
    call data_item(text, dims, values)
    call add(text, '  </Attribute>')
  end subroutine attribute

  !> A DataItem holding `values` (C order) of shape `dims`: nine significant
  !> digits, below a micrometre over a kilometre (the text of the formatted
  !> write '(*(1x, es16.8e3))', made by scientific_text).
  subroutine data_item(text, dims, values)
    type(text_t), intent(inout) :: text
    integer, intent(in) :: dims(:)
    real(wp), intent(in) :: values(:)
    character(len=width*per_line) :: line
    integer :: k, j
    call add(text, '    <DataItem Dimensions="'//dims_text(dims)//'" NumberType="Float" Precision="8" Format="XML">')
    do k = 1, size(values), per_line
      do j = k, min(k + per_line - 1, size(values))
        ! (no concatenation: a temporary per number)
        line((j - k)*width + 1:(j - k)*width + 1) = ' '
        line((j - k)*width + 2:(j - k + 1)*width) = scientific_text(values(j))
      end do
      call add(text, line(:(j - k)*width))
    end do
    call add(text, '    </DataItem>')
  end subroutine data_item

  !> A DataItem of shape `dims` holding `values` (formatted once) `times`
  !> over, in data_item's form.
  subroutine repeated_item(text, dims, values, times)
    type(text_t), intent(inout) :: text
    integer, intent(in) :: dims(:), times
    real(wp), intent(in) :: values(:)
    character(len=width*size(values)) :: once
    character(len=:), allocatable :: all
    integer :: k
    do k = 1, size(values)
      once((k - 1)*width + 1:k*width) = ' '//scientific_text(values(k))
    end do
    all = repeat(once, times)
    call add(text, '    <DataItem Dimensions="'//dims_text(dims)//'" NumberType="Float" Precision="8" Format="XML">')
    do k = 1, len(all), width*per_line
      call add(text, all(k:min(k + width*per_line - 1, len(all))))
    end do
    call add(text, '    </DataItem>')
  end subroutine repeated_item

  !> A DataItem naming the dataset `dataset` of shape `dims` in `file` (by
  !> the result's final file name: the .xmf sits beside it): 8-byte reals,
  !> or with floats = .false. the file's 4-byte integers.
  subroutine referenced_item(text, file, dims, dataset, floats)
    type(text_t), intent(inout) :: text
    type(result_file_t), intent(in) :: file
    integer, intent(in) :: dims(:)
    character(len=*), intent(in) :: dataset
    logical, intent(in) :: floats
    character(len=:), allocatable :: number_type
    number_type = 'NumberType="Int" Precision="4"'
    if (floats) number_type = 'NumberType="Float" Precision="8"'
    call add(text, '    <DataItem Dimensions="'//dims_text(dims)//'" '//number_type//' Format="HDF">'// &
             escaped(base_name(file%final_path()))//':'//escaped(dataset)//'</DataItem>')
  end subroutine referenced_item

  !> A node attribute of `kind` (Scalar, Vector) naming the dataset `dataset`.
  subroutine referenced_attribute(text, file, name, kind, dims, dataset)
    type(text_t), intent(inout) :: text
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, kind, dataset
    integer, intent(in) :: dims(:)
    call add(text, '  <Attribute Name="'//escaped(name)//'" AttributeType="'//kind//'" Center="Node">')
    call referenced_item(text, file, dims, dataset, file%is_real(dataset))
    call add(text, '  </Attribute>')
  end subroutine referenced_attribute

  !> Whether `dataset` holds numbers (real or integer, not text) that read back.
  logical function holds_numbers(file, dataset)
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: dataset
    real(wp), allocatable :: values(:)
    if (file%is_real(dataset)) then
      holds_numbers = .true.
      return
    end if
    values = file%values_of(dataset)   ! none for text
    holds_numbers = size(values) == product(file%shape_of(dataset)) .and. size(values) > 0
  end function holds_numbers

  pure logical function same_shape(a, b)
    integer, intent(in) :: a(:), b(:)
    same_shape = size(a) == size(b)
    if (same_shape) same_shape = all(a == b)
  end function same_shape

  !> Integers as lines of at most 3 per_line values (a connectivity).
  subroutine integer_lines(text, values)
    type(text_t), intent(inout) :: text
    integer, intent(in) :: values(:)
    character(len=12*3*per_line) :: line
    integer :: k
    do k = 1, size(values), 3*per_line
      write (line, '(*(i0, :, 1x))') values(k:min(k + 3*per_line - 1, size(values)))
      call add(text, '      '//trim(line))
    end do
  end subroutine integer_lines

  pure function dims_text(dims) result(text)
    integer, intent(in) :: dims(:)
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, size(dims)
      text = text//format_integer(dims(k))
      if (k < size(dims)) text = text//' '
    end do
  end function dims_text

  pure function base_name(path) result(name)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: name
    name = path(index(path, '/', back=.true.) + 1:)
  end function base_name

  !> Text safe inside XML attributes and elements.
  pure function escaped(text) result(xml)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: xml
    integer :: i
    if (scan(text, '&<>"') == 0) then
      xml = text
      return
    end if
    xml = ''
    do i = 1, len(text)
      select case (text(i:i))
      case ('&'); xml = xml//'&amp;'
      case ('<'); xml = xml//'&lt;'
      case ('>'); xml = xml//'&gt;'
      case ('"'); xml = xml//'&quot;'
      case default; xml = xml//text(i:i)
      end select
    end do
  end function escaped
end module io_xdmf
