!> numerics_random (MRG32k3a): the reference stream's first numbers, the
!> range, the mean, reproducibility and different seeds giving different
!> streams.
program test_random
  use base_kinds, only: wp
  use numerics_random, only: random_stream_t, new_random_stream, next_uniform
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  ! the first numbers of the default seed (12345 six times) from L'Ecuyer's
  ! recurrences (Operations Research 47(1), 1999, table 3: MRG32k3a) written
  ! out independently in Python integers; rtol 1e-15: the last division only
  real(wp), parameter :: reference(3) = [0.12701112204657714_wp, 0.3185275653967945_wp, 0.3091860155832701_wp]
  integer, parameter :: n = 10000
  type(random_stream_t) :: stream, copy, other
  real(wp) :: u, v, total
  logical :: inside, same, differ
  integer :: k

  do k = 1, 3
    call next_uniform(stream, u)
    call check_close(u, reference(k), 1e-15_wp, 0.0_wp, 'MRG32k3a reference stream, number')
  end do

  stream = new_random_stream(7)
  copy = stream
  other = new_random_stream(8)
  total = 0
  inside = .true.
  same = .true.
  differ = .false.
  do k = 1, n
    call next_uniform(stream, u)
    call next_uniform(copy, v)
    total = total + u
    inside = inside .and. u > 0 .and. u < 1
    same = same .and. u == v
    call next_uniform(other, v)
    differ = differ .or. u /= v
  end do
  call check(inside, 'every number in (0, 1)')
  call check(same, 'a copy of a stream gives the same numbers')
  call check(differ, 'seeds 7 and 8 give other numbers')
  ! the mean of n uniform numbers: standard deviation sqrt(1/(12 n)) = 0.0029; 4 of them
  call check(abs(total/n - 0.5_wp) <= 4*sqrt(1.0_wp/(12*n)), 'mean of 10000 numbers near 1/2')
  call finish_tests('test_random')
end program test_random
