def log = new File(basedir, 'build.log').text
// the missing ';' after the term on line 9 is reported with its location in Maven's form
assert log =~ /\[ERROR\] .*broken\.fcl:\[(9|10),\d+\] error FCL-S\d{3}: /
assert log.contains('BUILD FAILURE')
