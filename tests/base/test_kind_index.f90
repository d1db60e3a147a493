!> The index by name of a registry of kinds (base_kind_index), which both
!> factories keep: names in the order registered, an empty or taken name
!> refused with the registry's word for it, 0 for an unknown name, the
!> listing the unknown-kind messages show.
program test_kind_index
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use base_kind_index, only: kind_index_t
  use testing, only: check, finish_tests
  implicit none (type, external)

  type(kind_index_t) :: names
  type(status_t) :: st

  call check(names%find('plane') == 0 .and. names%listing() == '', 'an empty index knows no name')
  call names%add('plane', 'surface kind', st)
  call names%add('ellipsoid', 'surface kind', st)
  call check(st%ok(), 'two names added: '//st%text())
  call check(names%find('plane') == 1 .and. names%find('ellipsoid') == 2, 'the names in the order registered')
  call check(names%find('cone') == 0 .and. names%find('Plane') == 0, 'an unknown name (case counts) is 0')
  call check(names%listing() == ' ''plane'' ''ellipsoid''', 'the listing: '//names%listing())
  call names%add('plane', 'surface kind', st)
  call check(st%code == STATUS_INVALID_INPUT .and. st%text() == 'surface kind ''plane'' is registered already', &
             'a taken name is refused: '//st%text())
  st = status_t()
  call names%add('  ', 'force law kind', st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'force law kind') == 1 .and. &
             index(st%text(), 'needs a name') > 0, 'an empty name is refused: '//st%text())
  call check(names%find('ellipsoid') == 2 .and. names%listing() == ' ''plane'' ''ellipsoid''', &
             'a refused name leaves the index as it was')
  call names%add('cone', 'surface kind', st)
  call check(names%find('cone') == 0, 'nothing is added after a failed status (the caller''s error stands)')
  call finish_tests('test_kind_index')
end program test_kind_index
