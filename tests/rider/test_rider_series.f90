!> move_series (rider_series) moves every array of a ride's records, each
!> contact's included, into the result: the values arrive unchanged and
!> the source is left empty (moved, not copied).
program test_rider_series
  use base_kinds, only: wp
  use rider_model, only: N_CONTACTS
  use rider_series, only: ride_series_t, size_series, move_series
  use testing, only: check, finish_tests
  implicit none (type, external)

  type(ride_series_t) :: a, b
  integer :: k
  logical :: moved, emptied

  call size_series(a, 5, 6)
  a%n = 4
  a%time = [(0.1_wp*k, k = 1, 5)]
  a%state = 2
  a%extremes%located = .true.
  a%extremes%value(3) = 7
  do k = 1, N_CONTACTS
    associate (c => a%contact(k))
      c%u = k; c%v = k + 0.5_wp; c%arc_length = 10*k; c%wall_angle = -k; c%wall_distance = 3*k
      c%position = 4*k; c%velocity = 5*k; c%normal_force = 6*k; c%friction_force = 7*k
      c%drag_force = 8*k; c%in_water = mod(k, 2); c%reynolds = 9*k; c%drag_coefficient = 11*k
      c%projected_area = 12*k; c%relative_velocity = 13*k
    end associate
  end do

  call move_series(a, b)

  call check(b%n == 4 .and. b%capacity == 5, 'the count and the room moved')
  call check(allocated(b%time), 'the times moved')
  if (allocated(b%time)) call check(all(b%time == [(0.1_wp*k, k = 1, 5)]), 'the times unchanged')
  call check(allocated(b%state), 'the states moved')
  if (allocated(b%state)) call check(all(b%state == 2), 'the states unchanged')
  call check(b%extremes%located .and. b%extremes%value(3) == 7, 'the extremes moved')
  call check(.not. allocated(a%time) .and. .not. allocated(a%state), 'the ride''s arrays left empty')
  do k = 1, N_CONTACTS
    associate (c => b%contact(k))
      moved = allocated(c%u) .and. allocated(c%v) .and. allocated(c%arc_length) .and. &
              allocated(c%wall_angle) .and. allocated(c%wall_distance) .and. allocated(c%position) .and. &
              allocated(c%velocity) .and. allocated(c%normal_force) .and. allocated(c%friction_force) .and. &
              allocated(c%drag_force) .and. allocated(c%in_water) .and. allocated(c%reynolds) .and. &
              allocated(c%drag_coefficient) .and. allocated(c%projected_area) .and. allocated(c%relative_velocity)
      call check(moved, 'every array of a contact moved')
      if (.not. moved) cycle
      call check(all(c%u == k) .and. all(c%v == k + 0.5_wp) .and. all(c%arc_length == 10*k) .and. &
                 all(c%wall_angle == -k) .and. all(c%wall_distance == 3*k) .and. all(c%position == 4*k) .and. &
                 all(c%velocity == 5*k) .and. all(c%normal_force == 6*k) .and. all(c%friction_force == 7*k) .and. &
                 all(c%drag_force == 8*k) .and. all(c%in_water == mod(k, 2)) .and. all(c%reynolds == 9*k) .and. &
                 all(c%drag_coefficient == 11*k) .and. all(c%projected_area == 12*k) .and. &
                 all(c%relative_velocity == 13*k), 'a contact''s values unchanged')
      call check(size(c%position, 1) == 3 .and. size(c%position, 2) == 5, 'a contact''s shapes unchanged')
    end associate
    associate (c => a%contact(k))
      emptied = .not. (allocated(c%u) .or. allocated(c%v) .or. allocated(c%arc_length) .or. &
                       allocated(c%wall_angle) .or. allocated(c%wall_distance) .or. allocated(c%position) .or. &
                       allocated(c%velocity) .or. allocated(c%normal_force) .or. allocated(c%friction_force) .or. &
                       allocated(c%drag_force) .or. allocated(c%in_water) .or. allocated(c%reynolds) .or. &
                       allocated(c%drag_coefficient) .or. allocated(c%projected_area) .or. &
                       allocated(c%relative_velocity))
      call check(emptied, 'a contact''s arrays left empty (moved, not copied)')
    end associate
  end do
  call finish_tests('test_rider_series')
end program test_rider_series
