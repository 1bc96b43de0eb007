def log = new File(basedir, 'build.log').text
// the Extension file fails, naming the feature and the line that needs it (AND : PROD is on line 22)
assert log =~ /prod\.fcl:\[22,\d+\] needs extension level feature E-AND-PROD/
assert !(log =~ /valve\.fcl:\[\d+,\d+\] needs/)
assert log.contains('1 of 2 FCL file(s) checked')
assert log.contains('BUILD FAILURE')
