!> Uses slidesim's modules from an installed tree: a surface from the geometry
!> layer, the SHA-256 of the base layer, and a result file of the io layer.
program consumer
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_sha256, only: sha256_hex
  use geometry_surface, only: surface_point_t
  use geometry_elementary, only: ellipsoid_t
  use io_hdf5, only: result_file_t
  implicit none (type, external)
  type(ellipsoid_t) :: egg
  type(surface_point_t) :: p
  type(status_t) :: status
  type(result_file_t) :: file
  character(len=256) :: path

  egg = ellipsoid_t(2.0_wp, 1.5_wp, 1.0_wp, status)
  if (status%ok()) call egg%evaluate(0.0_wp, 0.0_wp, 1, p, status)
  ! at u = v = 0 the ellipsoid [a cos v cos u, b cos v sin u, c sin v] is at (a, 0, 0)
  if (.not. status%ok() .or. any(abs(p%r - [2.0_wp, 0.0_wp, 0.0_wp]) > 1e-15_wp)) error stop 'surface'
  if (sha256_hex('abc') /= 'ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad') error stop 'sha256'
  call get_command_argument(1, path)
  call file%create(trim(path), status)
  call file%write_scalar('/consumer/x', p%r(1), 'm', 'x of the ellipsoid at u = v = 0', status)
  call file%finish(status%ok(), 'ok', status)
  if (.not. status%ok()) error stop 'result file'
  print '(a)', 'consumer ok'
end program consumer
