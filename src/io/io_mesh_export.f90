!> The slide as CAD: the surface grid of a result file (/geometry/surface)
!> and, where the result has one, the water band between its edges
!> (/water/right_point, /water/left_point) as triangle meshes, written as
!> ASCII STL (one solid each: slide_surface, water_band) or OBJ (one object
!> each). Every quad of a grid is split into two triangles along the same
!> diagonal; all triangles of a mesh face the same side: the slide's face
!> away from its rows' centres (outwards of a tube or a half-pipe), the
!> water's up. Written through io_output_files' checked writer (a temporary
!> file renamed when complete; the paths claimed before the run like every
!> output). Layout: docs/outputs.md ("The slide as CAD").
module io_mesh_export
  use, intrinsic :: iso_c_binding, only: c_ptr, c_loc
  use hdf5, only: hid_t, hsize_t, h5open_f, h5fopen_f, h5fclose_f, H5F_ACC_RDONLY_F, h5lexists_f, &
                  h5dopen_f, h5dclose_f, h5dget_space_f, h5sget_simple_extent_ndims_f, &
                  h5sget_simple_extent_dims_f, h5sclose_f, h5dread_f, H5T_NATIVE_DOUBLE
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_IO
  use io_output_files, only: text_output_t
  implicit none (type, external)
  private
  public :: mesh_t, grid_mesh, mesh_area, export_result_meshes, write_stl, write_obj

  type :: mesh_t
    character(len=:), allocatable :: name
    real(wp), allocatable :: vertices(:, :)   !< 3 x n_vertices, m
    integer, allocatable :: triangles(:, :)   !< 3 x n_triangles, vertex numbers (1-based)
  end type mesh_t

contains

  !> The meshes of the result file `h5_path` written to `stl` and `obj`
  !> (empty: not written).
  subroutine export_result_meshes(h5_path, stl, obj, status)
    character(len=*), intent(in) :: h5_path, stl, obj
    type(status_t), intent(inout) :: status
    type(mesh_t), allocatable :: meshes(:)
    call result_meshes(h5_path, meshes, status)
    if (.not. status%ok()) return
    if (len(stl) > 0) call write_stl(stl, meshes, status)
    if (len(obj) > 0 .and. status%ok()) call write_obj(obj, meshes, status)
  end subroutine export_result_meshes

  !> The slide surface and the water band of a result file.
  subroutine result_meshes(h5_path, meshes, status)
    character(len=*), intent(in) :: h5_path
    type(mesh_t), allocatable, intent(out) :: meshes(:)
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: x(:, :), y(:, :), z(:, :), left(:, :), right(:, :)
    real(wp), allocatable :: grid(:, :, :)
    integer(hid_t) :: file_id
    integer :: hdferr
    allocate (meshes(0))
    call h5open_f(hdferr)
    call h5fopen_f(h5_path, H5F_ACC_RDONLY_F, file_id, hdferr)
    if (hdferr /= 0) then
      call set_status(status, STATUS_IO, h5_path//': cannot open the result file to export its surface')
      return
    end if
    call read_matrix(file_id, '/geometry/surface/x', x)
    call read_matrix(file_id, '/geometry/surface/y', y)
    call read_matrix(file_id, '/geometry/surface/z', z)
    call read_matrix(file_id, '/water/left_point', left)
    call read_matrix(file_id, '/water/right_point', right)
    call h5fclose_f(file_id, hdferr)
    if (size(x) == 0 .or. any(shape(y) /= shape(x)) .or. any(shape(z) /= shape(x))) then
      call set_status(status, STATUS_IO, h5_path//': the result has no surface grid (/geometry/surface) to export')
      return
    end if
    ! matrices as read: (n_v, n_u) of the file's (n_u, n_v)
    allocate (grid(3, size(x, 1), size(x, 2)))
    grid(1, :, :) = x
    grid(2, :, :) = y
    grid(3, :, :) = z
    meshes = [grid_mesh('slide_surface', grid)]
    call face_away_from_rows(meshes(1), grid)
    if (size(left, 2) >= 2 .and. size(left, 1) == 3 .and. all(shape(right) == shape(left))) then
      deallocate (grid)
      allocate (grid(3, 2, size(left, 2)))
      grid(:, 1, :) = right
      grid(:, 2, :) = left
      meshes = [meshes, grid_mesh('water_band', grid)]
      call face_up(meshes(2))
    end if
  end subroutine result_meshes

  !> A real dataset of rank 2 as the Fortran matrix HDF5 gives (its shape
  !> reversed); size 0 when absent.
  subroutine read_matrix(file_id, name, values)
    integer(hid_t), intent(in) :: file_id
    character(len=*), intent(in) :: name
    real(wp), allocatable, target, intent(out) :: values(:, :)
    integer(hid_t) :: dataset_id, space_id
    integer(hsize_t) :: dims(2), max_dims(2)
    type(c_ptr) :: buffer
    logical :: exists
    integer :: hdferr, rank, err
    allocate (values(0, 0))
    call h5lexists_f(file_id, name(:index(name, '/', back=.true.) - 1), exists, hdferr)
    if (hdferr /= 0 .or. .not. exists) return
    call h5lexists_f(file_id, name, exists, hdferr)
    if (hdferr /= 0 .or. .not. exists) return
    call h5dopen_f(file_id, name, dataset_id, hdferr)
    if (hdferr /= 0) return
    call h5dget_space_f(dataset_id, space_id, hdferr)
    call h5sget_simple_extent_ndims_f(space_id, rank, hdferr)
    if (rank == 2) call h5sget_simple_extent_dims_f(space_id, dims, max_dims, hdferr)
    call h5sclose_f(space_id, err)
    if (rank == 2 .and. hdferr >= 0) then
      deallocate (values)
      allocate (values(dims(1), dims(2)))   ! the Fortran API gives the dims reversed already
      buffer = c_loc(values)
      call h5dread_f(dataset_id, H5T_NATIVE_DOUBLE, buffer, hdferr)
      if (hdferr /= 0) then
        deallocate (values); allocate (values(0, 0))
      end if
    end if
    call h5dclose_f(dataset_id, err)
  end subroutine read_matrix

  !> The triangles of a structured grid of points (3, n1, n2): quad (i, j)
  !> as (i, j)-(i, j+1)-(i+1, j+1) and (i, j)-(i+1, j+1)-(i+1, j), all
  !> facing the side of d/dj x d/di.
  pure function grid_mesh(name, points) result(mesh)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: points(:, :, :)
    type(mesh_t) :: mesh
    integer :: n1, n2, i, j, t
    n1 = size(points, 2)
    n2 = size(points, 3)
    mesh%name = name
    mesh%vertices = reshape(points, [3, n1*n2])
    allocate (mesh%triangles(3, 2*max(n1 - 1, 0)*max(n2 - 1, 0)))
    t = 0
    do j = 1, n2 - 1
      do i = 1, n1 - 1
        mesh%triangles(:, t + 1) = [at(i, j), at(i, j + 1), at(i + 1, j + 1)]
        mesh%triangles(:, t + 2) = [at(i, j), at(i + 1, j + 1), at(i + 1, j)]
        t = t + 2
      end do
    end do
  contains
    pure integer function at(a, b)
      integer, intent(in) :: a, b
      at = a + (b - 1)*n1
    end function at
  end function grid_mesh

  !> Turns every triangle so that the mesh faces away from the centres of
  !> the grid's rows (the points of one index j): outwards of a tube.
  subroutine face_away_from_rows(mesh, points)
    type(mesh_t), intent(inout) :: mesh
    real(wp), intent(in) :: points(:, :, :)
    real(wp) :: centre(3, size(points, 3)), side
    integer :: t, row
    centre = sum(points, dim=2)/size(points, 2)
    side = 0
    do t = 1, size(mesh%triangles, 2)
      row = (mesh%triangles(1, t) - 1)/size(points, 2) + 1
      side = side + dot_product(normal(mesh, t), sum(mesh%vertices(:, mesh%triangles(:, t)), dim=2)/3 - &
                                centre(:, row))
    end do
    if (side < 0) call flip(mesh)
  end subroutine face_away_from_rows

  !> Turns every triangle so that the mesh faces up on the whole (+z).
  subroutine face_up(mesh)
    type(mesh_t), intent(inout) :: mesh
    real(wp) :: up, n(3)
    integer :: t
    up = 0
    do t = 1, size(mesh%triangles, 2)
      n = area_vector(mesh, t)
      up = up + n(3)
    end do
    if (up < 0) call flip(mesh)
  end subroutine face_up

  subroutine flip(mesh)
    type(mesh_t), intent(inout) :: mesh
    mesh%triangles([2, 3], :) = mesh%triangles([3, 2], :)
  end subroutine flip

  !> Twice the area times the unit normal of triangle t (right-hand order).
  pure function area_vector(mesh, t) result(n)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: t
    real(wp) :: n(3), a(3), b(3)
    a = mesh%vertices(:, mesh%triangles(2, t)) - mesh%vertices(:, mesh%triangles(1, t))
    b = mesh%vertices(:, mesh%triangles(3, t)) - mesh%vertices(:, mesh%triangles(1, t))
    n = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
  end function area_vector

  pure function normal(mesh, t) result(n)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: t
    real(wp) :: n(3)
    n = area_vector(mesh, t)
    if (norm2(n) > 0) n = n/norm2(n)
  end function normal

  !> The area of a mesh (m^2).
  pure real(wp) function mesh_area(mesh) result(area)
    type(mesh_t), intent(in) :: mesh
    integer :: t
    area = 0
    do t = 1, size(mesh%triangles, 2)
      area = area + 0.5_wp*norm2(area_vector(mesh, t))
    end do
  end function mesh_area

  !> ASCII STL: one solid per mesh.
  subroutine write_stl(path, meshes, status)
    character(len=*), intent(in) :: path
    type(mesh_t), intent(in) :: meshes(:)
    type(status_t), intent(inout) :: status
    type(text_output_t) :: out
    integer :: m, t, k
    call out%create(path, 'the STL export', status)
    if (.not. status%ok()) return
    do m = 1, size(meshes)
      call out%write_line('solid '//meshes(m)%name)
      do t = 1, size(meshes(m)%triangles, 2)
        call out%write_line('  facet normal'//numbers(normal(meshes(m), t)))
        call out%write_line('    outer loop')
        do k = 1, 3
          call out%write_line('      vertex'//numbers(meshes(m)%vertices(:, meshes(m)%triangles(k, t))))
        end do
        call out%write_line('    endloop')
        call out%write_line('  endfacet')
      end do
      call out%write_line('endsolid '//meshes(m)%name)
    end do
    call out%finish(status)
  end subroutine write_stl

  !> Wavefront OBJ: one object per mesh, vertices numbered across the file.
  subroutine write_obj(path, meshes, status)
    character(len=*), intent(in) :: path
    type(mesh_t), intent(in) :: meshes(:)
    type(status_t), intent(inout) :: status
    type(text_output_t) :: out
    character(len=40) :: face
    integer :: m, t, k, offset
    call out%create(path, 'the OBJ export', status)
    if (.not. status%ok()) return
    call out%write_line('# slidesim: the slide surface and the water band, metres')
    offset = 0
    do m = 1, size(meshes)
      call out%write_line('o '//meshes(m)%name)
      do k = 1, size(meshes(m)%vertices, 2)
        call out%write_line('v'//numbers(meshes(m)%vertices(:, k)))
      end do
      do t = 1, size(meshes(m)%triangles, 2)
        write (face, '(a, 3(1x, i0))') 'f', meshes(m)%triangles(:, t) + offset
        call out%write_line(trim(face))
      end do
      offset = offset + size(meshes(m)%vertices, 2)
    end do
    call out%finish(status)
  end subroutine write_obj

  !> Three numbers, each after a blank, nine significant digits.
  function numbers(x) result(text)
    real(wp), intent(in) :: x(3)
    character(len=54) :: text
    write (text, '(3(1x, es17.9e3))') x
  end function numbers
end module io_mesh_export
