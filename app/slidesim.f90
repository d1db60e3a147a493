program slidesim
  implicit none (type, external)
  print '(a)', 'slidesim'
end program slidesim
