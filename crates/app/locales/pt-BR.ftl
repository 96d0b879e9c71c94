### rlc

rlc-axis-current = corrente i
rlc-axis-voltage = tensão no capacitor v_C
rlc-envelope = envoltória
rlc-series-critical = R crítica = { $resistance }
rlc-schematic = Circuito RLC série em t = { $time }: corrente { $current }, capacitor em { $voltage }.
rlc-describe-current-undamped = R = { $resistance }, não amortecido (um circuito LC sem perdas): a corrente oscila indefinidamente em ω₀ = { $frequency }, entre ±{ $bound } (toda a energia passa para o indutor e volta a cada meio período).
rlc-describe-voltage-undamped = R = { $resistance }, não amortecido (um circuito LC sem perdas): a tensão no capacitor oscila indefinidamente entre +{ $voltage } e −{ $voltage } em ω₀ = { $frequency }.
rlc-describe-current-underdamped = R = { $resistance }, abaixo da resistência crítica { $critical }, subamortecido: a corrente oscila em ω_d = { $frequency } (Q = { $q }), decaindo como e^(−αt) com α = { $alpha }; nunca ultrapassa { $bound }.
rlc-describe-voltage-underdamped = R = { $resistance }, abaixo da resistência crítica { $critical }, subamortecido: a tensão no capacitor { $reversal ->
        [slight] se inverte apenas levemente (no máximo { $rebound } de V₀, dentro da faixa)
        [count] { $crossings ->
            [one] inverte a polaridade uma vez antes de se acomodar
           *[other] inverte a polaridade { $crossings } vezes antes de se acomodar
        }
       *[never] nunca inverte a polaridade
    } e { $settles ->
        [yes] fica dentro de 5 % de V₀ após { $time }
       *[no] nunca se acomoda
    }.
rlc-describe-current-critical = R = { $resistance }, igual à resistência crítica, criticamente amortecido: um único pulso de corrente (negativo, com o capacitor se descarregando) que volta a zero sem inverter; a corrente nunca ultrapassa { $bound }.
rlc-describe-voltage-critical = R = { $resistance }, igual à resistência crítica, criticamente amortecido: o capacitor se descarrega o mais rápido possível sem inverter; a tensão { $settles ->
        [yes] fica dentro de 5 % de V₀ após { $time }
       *[no] nunca se acomoda
    }.
rlc-describe-current-overdamped = R = { $resistance }, acima da resistência crítica { $critical }, superamortecido: um pulso lento de corrente (negativo, com o capacitor se descarregando) sem inverter, constante de tempo lenta { $time }.
rlc-describe-voltage-overdamped = R = { $resistance }, acima da resistência crítica { $critical }, superamortecido: o capacitor se descarrega lentamente sem inverter; a tensão { $settles ->
        [yes] fica dentro de 5 % de V₀ após { $time }
       *[no] nunca se acomoda
    }.
rlc-title = Circuito RLC série
rlc-summary = Um capacitor carregado com V₀ é ligado em t = 0 a uma malha com um indutor e um resistor. A carga q obedece à mesma equação de uma massa presa a uma mola: L faz o papel da massa, R o do amortecedor e 1/C o da mola. Com R abaixo da resistência crítica 2√(L/C), a energia vai e volta entre C e L e a corrente oscila em ω_d, decaindo como e^(−αt), α = R/(2L); com R = 2√(L/C), o capacitor se descarrega o mais rápido possível sem inverter; acima disso, a descarga volta a ser mais lenta. Q = 1/(2ζ) mede o quanto o circuito oscila, e R/L é a largura de banda de meia potência da ressonância da corrente: sob uma tensão senoidal, |I|² fica acima da metade do seu pico numa faixa de exatamente R/L rad/s, para qualquer R. A corrente é negativa enquanto o capacitor se descarrega (i = dq/dt).
rlc-param-R = resistência
rlc-param-L = indutância
rlc-param-C = capacitância
rlc-param-V0 = tensão inicial no capacitor
rlc-readout-regime = regime
rlc-readout-w0 = frequência de ressonância ω₀ = 1/√(LC)
rlc-readout-f0 = frequência de ressonância f₀
rlc-readout-alpha = taxa de decaimento α = R/(2L)
rlc-readout-zeta = razão de amortecimento ζ
rlc-readout-Q = fator de qualidade Q = 1/(2ζ)
rlc-readout-bandwidth = largura de banda de meia potência da ressonância da corrente Δω = R/L
rlc-readout-R-crit = resistência crítica 2√(L/C)
rlc-readout-wd = frequência de oscilação ω_d
rlc-readout-settling-time = v_C dentro de 5 % de V₀ após
rlc-plot-current = Corrente i(t)
rlc-plot-voltage = Tensão no capacitor v_C(t)
rlc-preset-1 = LC sem perdas, R = 0
rlc-preset-2 = Oscilante, R = 2 Ω
rlc-preset-3 = Subamortecido, R = 5 Ω
rlc-preset-4 = Crítico, R = 10 Ω
rlc-preset-5 = Superamortecido, R = 20 Ω

