!> XDMF files for ParaView and VisIt next to a result file: XML that points at
!> the datasets of the HDF5 file by path (nothing is copied), in the XDMF 2
!> form that ParaView's "XDMF Reader" and VisIt read (checked with ParaView's
!> own reader by tests/cli/xdmf_files.sh):
!> - a surface grid as a structured grid (2DSMesh, X_Y_Z geometry);
!> - paths (streamline, point-mass path, centerline, body and contact paths)
!>   as one polyline each, with every real (n) and (n, 3) dataset of their
!>   group as node scalars and vectors;
!> - the water band as a 2 x n structured grid between the two edges
!>   (JOIN of the edge datasets), with speed and height on its nodes;
!> - moving points (bodies, contacts) as a temporal collection: at most
!>   max_steps time steps (every k-th sample and the last), each a set of
!>   points taken from the position datasets by hyperslabs (JOIN of rows).
!> Layout: docs/outputs.md ("ParaView and VisIt").
module io_xdmf
  use base_kinds, only: wp
  use base_text, only: format_integer, format_real
  use base_status, only: status_t
  use io_hdf5, only: result_file_t
  implicit none (type, external)
  private
  public :: xdmf_t, xdmf_path, attach_surface_view

  integer, parameter :: max_steps = 200   ! time steps of a temporal collection

  type :: xdmf_t
    private
    character(len=:), allocatable :: xml, h5
    integer :: used = 0   ! characters of xml in use (xml grows by doubling: appending stays linear)
  contains
    procedure :: start => xdmf_start
    procedure :: surface => xdmf_surface
    procedure :: polyline => xdmf_polyline
    procedure :: band => xdmf_band
    procedure :: moving_points => xdmf_moving_points
    procedure :: attach => xdmf_attach
  end type xdmf_t

  !> The text of one row of a dataset, without the row index between head and tail.
  type :: row_text_t
    character(len=:), allocatable :: head, tail
  end type row_text_t

contains

  !> The XDMF file next to a result: `<name>.xmf` for `<name>.h5`, else the
  !> result's name with `.xmf` appended.
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

  !> Begins the XML for the result file at `h5_path` (referenced by its file
  !> name, so the two files can move together).
  subroutine xdmf_start(self, h5_path)
    class(xdmf_t), intent(inout) :: self
    character(len=*), intent(in) :: h5_path
    self%h5 = h5_path(index(h5_path, '/', back=.true.) + 1:)
    ! no XML comment: ParaView's XDMF 2 reader reports an expression syntax error on some
    self%used = 0
    call add(self, '<?xml version="1.0" ?>')
    call add(self, '<Xdmf Version="2.0">')
    call add(self, '<Domain>')
  end subroutine xdmf_start

  !> The surface grid of io_surface_grid (group/x, y, z of shape (n_u, n_v)).
  subroutine xdmf_surface(self, file, name, group)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, group
    integer, allocatable :: dims(:)
    dims = file%shape_of(group//'/x')
    if (size(dims) /= 2) return
    call add(self, '<Grid Name="'//escaped(name)//'" GridType="Uniform">')
    call add(self, '  <Topology TopologyType="2DSMesh" Dimensions="'//dims_text(dims)//'"/>')
    call add(self, '  <Geometry GeometryType="X_Y_Z">')
    call add(self, '    '//data_item(self, file, group//'/x'))
    call add(self, '    '//data_item(self, file, group//'/y'))
    call add(self, '    '//data_item(self, file, group//'/z'))
    call add(self, '  </Geometry>')
    call add(self, '</Grid>')
  end subroutine xdmf_surface

  !> A polyline through the rows of `points` (shape (n, 3)) with the real
  !> datasets of `group` of shape (n) or (n, 3) as node attributes.
  subroutine xdmf_polyline(self, file, name, points, group)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, points, group
    integer, allocatable :: dims(:), d(:)
    character(len=:), allocatable :: names(:)
    integer :: k
    dims = file%shape_of(points)
    if (size(dims) /= 2) return
    if (dims(1) < 2) return
    call add(self, '<Grid Name="'//escaped(name)//'" GridType="Uniform">')
    call add(self, '  <Topology TopologyType="Polyline" NodesPerElement="'//format_integer(dims(1))// &
             '" NumberOfElements="1"/>')
    call add(self, '  <Geometry GeometryType="XYZ">')
    call add(self, '    '//data_item(self, file, points))
    call add(self, '  </Geometry>')
    names = file%names_in(group)
    do k = 1, size(names)
      if (trim(names(k)) == points .or. .not. file%is_real(trim(names(k)))) cycle
      d = file%shape_of(trim(names(k)))
      if (size(d) == 0) cycle
      if (d(1) /= dims(1)) cycle
      if (size(d) == 1) then
        call attribute(self, file, trim(names(k)), 'Scalar')
      else if (size(d) == 2) then
        if (d(2) == 3) call attribute(self, file, trim(names(k)), 'Vector')
      end if
    end do
    call add(self, '</Grid>')
  end subroutine xdmf_polyline

  !> The band between two edges (shape (n, 3) each) as a 2 x n structured
  !> grid; `fields` (shape (n)) on both edges' nodes.
  subroutine xdmf_band(self, file, name, first_edge, second_edge, fields)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, first_edge, second_edge
    character(len=*), intent(in) :: fields(:)
    integer, allocatable :: dims(:)
    integer :: k
    dims = file%shape_of(first_edge)
    if (size(dims) /= 2) return
    if (dims(1) < 2) return
    call add(self, '<Grid Name="'//escaped(name)//'" GridType="Uniform">')
    call add(self, '  <Topology TopologyType="2DSMesh" Dimensions="2 '//format_integer(dims(1))//'"/>')
    call add(self, '  <Geometry GeometryType="XYZ">')
    call add(self, '    <DataItem ItemType="Function" Function="JOIN($0 ; $1)" Dimensions="'// &
             format_integer(2*dims(1))//' 3">')
    call add(self, '      '//data_item(self, file, first_edge))
    call add(self, '      '//data_item(self, file, second_edge))
    call add(self, '    </DataItem>')
    call add(self, '  </Geometry>')
    do k = 1, size(fields)
      call add(self, '  <Attribute Name="'//base_name(trim(fields(k)))//'" AttributeType="Scalar" Center="Node">')
      call add(self, '    <DataItem ItemType="Function" Function="JOIN($0 ; $0)" Dimensions="'// &
               format_integer(2*dims(1))//'">')
      call add(self, '      '//data_item(self, file, trim(fields(k))))
      call add(self, '    </DataItem>')
      call add(self, '  </Attribute>')
    end do
    call add(self, '</Grid>')
  end subroutine xdmf_band

  !> Points moving over time: a temporal collection; at each kept time step
  !> one point per dataset in `points` (each of shape (n, 3)), joined by a
  !> polyline when `connect`. No node fields: ParaView's XDMF 2 reader fails
  !> to parse a JOIN of one-value hyperslabs (their values are on the paths).
  !> The text that does not change from step to step is made once (a step
  !> differs only in its time and row index).
  subroutine xdmf_moving_points(self, file, name, time, points, connect)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: time(:)
    character(len=*), intent(in) :: points(:)
    logical, intent(in) :: connect
    integer :: n, stride, i, k, m
    character(len=:), allocatable :: join, grid, topology
    type(row_text_t), allocatable :: rows(:)
    n = size(time)
    m = size(points)
    if (n < 1 .or. m < 1) return
    stride = (n + max_steps - 1)/max_steps
    join = 'JOIN($0'
    do k = 1, m - 1
      join = join//' ; $'//format_integer(k)
    end do
    join = join//')'
    grid = '  <Grid Name="'//escaped(name)//'" GridType="Uniform">'
    if (connect .and. m > 1) then
      topology = '    <Topology TopologyType="Polyline" NodesPerElement="'//format_integer(m)//'" NumberOfElements="1"/>'
    else
      topology = '    <Topology TopologyType="Polyvertex" NodesPerElement="1" NumberOfElements="'// &
                 format_integer(m)//'"/>'
    end if
    ! row k of a step: its head, the row index, its tail (one dataset: the row
    ! itself; XDMF's expression parser refuses a JOIN of one)
    allocate (rows(m))
    do k = 1, m
      rows(k) = row_text(self, file, trim(points(k)), repeat(' ', merge(6, 8, m == 1)))
    end do
    call add(self, '<Grid Name="'//escaped(name)//'" GridType="Collection" CollectionType="Temporal">')
    i = 1
    do
      call add(self, grid)
      call add(self, '    <Time Value="'//format_real(time(i))//'"/>')
      call add(self, topology)
      call add(self, '    <Geometry GeometryType="XYZ">')
      if (m > 1) call add(self, '      <DataItem ItemType="Function" Function="'//join//'" Dimensions="'// &
                          format_integer(m)//' 3">')
      do k = 1, m
        call add(self, rows(k)%head//format_integer(i - 1)//rows(k)%tail)
      end do
      if (m > 1) call add(self, '      </DataItem>')
      call add(self, '    </Geometry>')
      call add(self, '  </Grid>')
      if (i == n) exit
      i = min(i + stride, n)
    end do
    call add(self, '</Grid>')
  end subroutine xdmf_moving_points

  !> Closes the XML and hands it to the result file, which writes it next to
  !> itself (xdmf_path) as it finishes: both files are kept, or neither.
  subroutine xdmf_attach(self, file, status)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(inout) :: file
    type(status_t), intent(in) :: status   !< nothing is attached to a file whose writes failed
    if (.not. status%ok()) return
    call add(self, '</Domain>')
    call add(self, '</Xdmf>')
    call file%add_companion(xdmf_path(file%final_path()), self%xml(:self%used))
  end subroutine xdmf_attach

  !> The view of one surface grid alone (`dataset`, e.g. the slide's
  !> '/geometry/surface' of the identification scenarios), named `name`.
  subroutine attach_surface_view(file, name, dataset, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: name, dataset
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    call xdmf%start(file%final_path())
    call xdmf%surface(file, name, dataset)
    call xdmf%attach(file, status)
  end subroutine attach_surface_view

  subroutine add(self, line)
    class(xdmf_t), intent(inout) :: self
    character(len=*), intent(in) :: line
    character(len=:), allocatable :: grown
    integer :: n
    n = self%used + len(line) + 1
    if (.not. allocated(self%xml)) allocate (character(len=max(4096, 2*n)) :: self%xml)
    if (n > len(self%xml)) then
      allocate (character(len=max(2*len(self%xml), n)) :: grown)
      grown(:self%used) = self%xml(:self%used)
      call move_alloc(grown, self%xml)
    end if
    self%xml(self%used + 1:n - 1) = line
    self%xml(n:n) = new_line('a')
    self%used = n
  end subroutine add

  !> A node attribute from a dataset (Scalar: shape (n); Vector: (n, 3)).
  subroutine attribute(self, file, name, kind)
    class(xdmf_t), intent(inout) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, kind
    call add(self, '  <Attribute Name="'//base_name(name)//'" AttributeType="'//kind//'" Center="Node">')
    call add(self, '    '//data_item(self, file, name))
    call add(self, '  </Attribute>')
  end subroutine attribute

  !> The DataItem of a whole real dataset of the HDF5 file.
  function data_item(self, file, name) result(text)
    class(xdmf_t), intent(in) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: text
    text = '<DataItem Dimensions="'//dims_text(file%shape_of(name))//'" NumberType="Float" Precision="8" '// &
           'Format="HDF">'//escaped(self%h5)//':'//escaped(name)//'</DataItem>'
  end function data_item

  !> Row i (1-based) of a dataset of shape (n) or (n, 3) as a HyperSlab:
  !> head//(i - 1)//tail, the head indented by `indent`.
  function row_text(self, file, name, indent) result(text)
    class(xdmf_t), intent(in) :: self
    type(result_file_t), intent(in) :: file
    character(len=*), intent(in) :: name, indent
    type(row_text_t) :: text
    integer, allocatable :: dims(:)
    character(len=*), parameter :: nl = new_line('a')
    dims = file%shape_of(name)
    if (size(dims) == 1) then
      text%head = indent//'<DataItem ItemType="HyperSlab" Dimensions="1" Type="HyperSlab">'//nl// &
                  '          <DataItem Dimensions="3 1" Format="XML">'
      text%tail = ' 1 1</DataItem>'//nl
    else
      text%head = indent//'<DataItem ItemType="HyperSlab" Dimensions="1 '//format_integer(dims(2))// &
                  '" Type="HyperSlab">'//nl//'          <DataItem Dimensions="3 2" Format="XML">'
      text%tail = ' 0 1 1 1 '//format_integer(dims(2))//'</DataItem>'//nl
    end if
    text%tail = text%tail//'          '//data_item(self, file, name)//nl//'        </DataItem>'
  end function row_text

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
    name = escaped(path(index(path, '/', back=.true.) + 1:))
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
