def log = new File(basedir, 'build.log').text
// the SPI itself resolves; everything behind it does not
assert !log.contains('package org.fclcert.iut.spi does not exist')
assert log.contains('package org.fclcert.eval does not exist')
assert log.contains('package org.antlr.v4.runtime does not exist')
assert log.contains('package com.fasterxml.jackson.databind does not exist')
assert log.contains('package picocli does not exist')
assert log.contains('COMPILATION ERROR')
assert log.contains('BUILD FAILURE')
